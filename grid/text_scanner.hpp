#pragma once
// Reads whitespace-separated numbers from a text file, counting lines, for the small text formats
// no library covers (the classic sorting-benchmark .off, x y z s point lists). '#' starts a comment.
#include <cstdint>
#include <fstream>
#include <string>

namespace cellproj {

class TextScanner {
 public:
  explicit TextScanner(const std::string& path);
  // The next number; throws InputError naming the file, the line and what was expected.
  double number(const char* what);
  std::int64_t integer(const char* what);
  bool at_end();  // only white space and comments left
  int line() const { return line_; }

 private:
  bool next_token(std::string& tok);
  std::string path_;
  std::ifstream in_;
  std::string buf_;
  std::size_t pos_ = 0;
  int line_ = 0;
};

}  // namespace cellproj
