#pragma once
// An allocator for the large buffers a frame writes once (the framebuffer, the fragment batches):
// blocks of 2 MB or more are aligned to 2 MB and marked for transparent huge pages (Linux
// madvise), so first touching them costs one page fault per 2 MB instead of one per 4 KB. A fault
// costs microseconds on a virtual machine: a fresh 1024² framebuffer (16 MB) was 4096 of them.
// Where the kernel gives no huge pages (THP off, other systems) it is the plain allocator.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace cellproj {

inline constexpr std::size_t kHugePage = std::size_t(2) << 20;

// Marks [p, p + bytes) for transparent huge pages where it holds whole ones. Advice only.
inline void advise_huge_pages(void* p, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  const auto begin = reinterpret_cast<std::uintptr_t>(p), end = begin + bytes;
  const std::uintptr_t first = (begin + kHugePage - 1) / kHugePage * kHugePage, last = end / kHugePage * kHugePage;
  if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
#else
  (void)p, (void)bytes;
#endif
}

template <class T>
struct HugePageAllocator {
  using value_type = T;
  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

  // A large block is a plain malloc block 2 MB longer than asked, the 2 MB boundary inside it
  // handed out and the block's start kept in the word before. Not aligned_alloc: the C library
  // carves an aligned block out of a larger free one and frees the two ends apart, so the same
  // request a frame later no longer fits the hole it left; from the heap (below the mapping
  // threshold the command line sets) every frame took fresh memory, 16 MB a frame at 1024².
  T* allocate(std::size_t n) {
    if (n > (static_cast<std::size_t>(-1) - 2 * kHugePage) / sizeof(T)) throw std::bad_array_new_length();
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kHugePage) return static_cast<T*>(::operator new(bytes));
    const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
    void* block = std::malloc(rounded + kHugePage);
    if (!block) throw std::bad_alloc();
    // The first boundary past the stored word: at most kHugePage on (malloc aligns to 16 bytes).
    const auto at = (reinterpret_cast<std::uintptr_t>(block) + sizeof(void*) + kHugePage - 1) / kHugePage * kHugePage;
    void* p = reinterpret_cast<void*>(at);
    static_cast<void**>(p)[-1] = block;
    advise_huge_pages(p, rounded);  // (the rounded length lies inside the block)
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) < kHugePage)
      ::operator delete(p);
    else
      std::free(reinterpret_cast<void**>(p)[-1]);
  }
  friend bool operator==(const HugePageAllocator&, const HugePageAllocator&) { return true; }
  friend bool operator!=(const HugePageAllocator&, const HugePageAllocator&) { return false; }
};

// An array a frame (or a batch) writes afresh: the framebuffer, the fragment batches, and the
// per-point, per-cell and per-face arrays of a view. In huge pages once 2 MB or more. Where a
// frame allocates blocks beyond malloc's mapping threshold (32 MB at most), the C library maps
// those anew and trims its heaps, and the frame's other large arrays fault in again every frame:
// 12,500 faults a frame for bench/swirl_scene.sh's million hexahedra, 400 to 1,900 with the sort's
// arrays and the screen points in huge pages (docs/methods.md, "Fresh pages").
template <class T>
using FrameBuffer = std::vector<T, HugePageAllocator<T>>;

// Reserves room for n elements of a plain std::vector and asks for huge pages over it before a
// pass first touches it: for the large arrays a mesh prepares once (its face topology, the
// sorter's face planes), whose type stays std::vector. Filling a fresh 48 MB array took 0.17 s in
// 4 KB pages on this project's virtual machine, 0.01 s in huge pages. Advice only: a block malloc
// hands back already touched keeps the pages it has.
template <class T>
void reserve_in_huge_pages(std::vector<T>& v, std::size_t n) {
  v.reserve(n);
  advise_huge_pages(v.data(), n * sizeof(T));
}

// The C library's settings for a program that renders frame after frame (the command line sets
// them at start). glibc maps each block above its threshold anew and unmaps it when freed, so a
// frame's arrays of a few MB would fault in again every frame; its threshold rises to 32 MB only
// once such a block has been freed, which depended on what the mesh's preparation happened to
// allocate (1,375 faults a frame on the 1M box against 118). Fixed at 32 MB from the start, the
// heap trimmed past 64 MB (docs/methods.md, "The C library's mapping threshold"). Process-wide:
// the library itself leaves them to the program, whose frames then fault one page per 2 MB of
// each FrameBuffer (820 faults a frame on the 1M box, none with these settings).
inline void keep_frame_arrays_in_heap() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 64 << 20);
#endif
}

}  // namespace cellproj
