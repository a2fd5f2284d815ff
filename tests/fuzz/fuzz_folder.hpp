#pragma once
// The folder a fuzzing process writes its inputs to: one per process, under $TMPDIR (bench/fuzz.sh
// gives each run its own and removes it afterwards: libFuzzer's forked jobs end by signals and
// timeouts that skip any clean-up of their own), else under /tmp.
#include <unistd.h>

#include <cstdlib>
#include <string>

inline std::string make_fuzz_folder() {
  const char* tmp = std::getenv("TMPDIR");
  std::string name = std::string(tmp && *tmp ? tmp : "/tmp") + "/cellproj-fuzz-XXXXXX";
  if (!mkdtemp(name.data())) std::abort();
  return name;
}
