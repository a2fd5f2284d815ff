#include "io/xml_attribute.hpp"

#include <algorithm>

namespace cellproj {

std::optional<std::string> xml_attribute(const std::string& tag, const std::string& name) {
  // XML's attribute syntax: name, optional white space, '=', optional white space, a value in double
  // or single quotes (a fuzzed offset   ="808" was missed by a plain search for offset=", and VTK,
  // reading it, sized a garbled block header's 7 GB).
  static const char* space = " \t\r\n";
  std::size_t k = tag.find_first_of(space);  // past the element's name
  while (k != std::string::npos && (k = tag.find_first_not_of(space, k)) != std::string::npos) {
    const std::size_t key_end = std::min(tag.find_first_of(" \t\r\n=", k), tag.size());
    const std::size_t eq = tag.find_first_not_of(space, key_end);
    if (eq == std::string::npos || tag[eq] != '=') {  // not an attribute ("/" of an empty tag): go on
      k = eq;
      continue;
    }
    const std::size_t quote = tag.find_first_not_of(space, eq + 1);
    if (quote == std::string::npos || (tag[quote] != '"' && tag[quote] != '\'')) return std::nullopt;
    const std::size_t close = tag.find(tag[quote], quote + 1);
    if (close == std::string::npos) return std::nullopt;
    if (tag.compare(k, key_end - k, name) == 0 && key_end - k == name.size())
      return tag.substr(quote + 1, close - quote - 1);
    k = close + 1;
  }
  return std::nullopt;
}

}  // namespace cellproj
