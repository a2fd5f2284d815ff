#pragma once
// CELLPROJ_AVX2_CLONES before a function: it is compiled twice, for the build's target and for
// AVX2, and the processor picks one when the library loads (target_clones, on x86-64 with GCC or
// clang). Its loops that vectorize then run four doubles wide where the processor can. On other
// processors: the build's target only.
// CELLPROJ_AVX2_DISPATCH is 1 where code may also be built for AVX2 and chosen at run time.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define CELLPROJ_AVX2_DISPATCH 1
#define CELLPROJ_AVX2_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define CELLPROJ_AVX2_DISPATCH 0
#define CELLPROJ_AVX2_CLONES
#endif
