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
  // Line-record formats (TetGen's, read line by line): start the next record on the next line that
  // is not blank or a comment (what is left of the current one is skipped), then read fields from
  // that line only, each a clear error when the line ends early.
  void next_record(const char* what);
  double field(const char* what);
  std::int64_t integer_field(const char* what);
  int line() const { return line_; }

 private:
  bool next_token(std::string& tok);
  double parse(const std::string& tok, const char* what) const;
  static std::int64_t whole(double v, int line, const std::string& path, const char* what);
  std::string path_;
  std::ifstream in_;
  std::string buf_;
  std::size_t pos_ = 0;
  int line_ = 0;
};

}  // namespace cellproj
