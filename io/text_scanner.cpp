#include "io/text_scanner.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "base/error.hpp"

namespace cellproj {

TextScanner::TextScanner(const std::string& path) : path_(path), in_(path) {
  if (!in_) throw InputError(where(path, "cannot open"));
}

bool TextScanner::next_token(std::string& tok) {
  for (;;) {
    while (pos_ < buf_.size() && std::isspace(static_cast<unsigned char>(buf_[pos_]))) ++pos_;
    if (pos_ < buf_.size() && buf_[pos_] != '#') break;
    if (!std::getline(in_, buf_)) return false;
    ++line_;
    pos_ = 0;
  }
  const std::size_t start = pos_;
  while (pos_ < buf_.size() && !std::isspace(static_cast<unsigned char>(buf_[pos_]))) ++pos_;
  tok = buf_.substr(start, pos_ - start);
  return true;
}

double TextScanner::number(const char* what) {
  std::string tok;
  if (!next_token(tok))
    throw InputError(where(
        path_, "file ends (after line " + std::to_string(line_) + ") where " + what + " was expected: truncated?"));
  return parse(tok, what);
}

double TextScanner::parse(const std::string& tok, const char* what) const {
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(tok.c_str(), &end);
  if (end != tok.c_str() + tok.size() || errno == ERANGE)
    throw InputError(where(path_, "line " + std::to_string(line_) + ": '" + tok + "' is not a number (" + what + ")"));
  return v;
}

std::int64_t TextScanner::whole(double v, int line, const std::string& path, const char* what) {
  if (v != std::floor(v) || std::abs(v) > 9.0e15)
    throw InputError(
        where(path, "line " + std::to_string(line) + ": " + std::to_string(v) + " is not an integer (" + what + ")"));
  return static_cast<std::int64_t>(v);
}

std::int64_t TextScanner::integer(const char* what) { return whole(number(what), line_, path_, what); }

void TextScanner::next_record(const char* what) {
  pos_ = buf_.size();  // the rest of the current line is not part of the next record
  std::string tok;
  if (!next_token(tok))
    throw InputError(where(
        path_, "file ends (after line " + std::to_string(line_) + ") where " + what + " was expected: truncated?"));
  pos_ -= tok.size();
}

double TextScanner::field(const char* what) {
  while (pos_ < buf_.size() && std::isspace(static_cast<unsigned char>(buf_[pos_]))) ++pos_;
  if (pos_ >= buf_.size() || buf_[pos_] == '#')
    throw InputError(where(path_, "line " + std::to_string(line_) + ": the record ends where " + what +
                                      " was expected (a record is one line)"));
  const std::size_t start = pos_;
  while (pos_ < buf_.size() && !std::isspace(static_cast<unsigned char>(buf_[pos_]))) ++pos_;
  return parse(buf_.substr(start, pos_ - start), what);
}

std::int64_t TextScanner::integer_field(const char* what) { return whole(field(what), line_, path_, what); }

bool TextScanner::at_end() {
  std::string tok;
  if (!next_token(tok)) return true;
  pos_ -= tok.size();
  return false;
}

}  // namespace cellproj
