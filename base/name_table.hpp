#pragma once
// The names of an enum's values on the command line and in files, from one table per enum:
// parsing (an InputError listing the known names), printing, and the list for help texts.
#include <cstddef>
#include <string>
#include <utility>

#include "base/error.hpp"

namespace cellproj {

template <class E, std::size_t N>
using NameTable = std::pair<E, const char*>[N];

// "a, b, c"
template <class E, std::size_t N>
std::string names(const NameTable<E, N>& table) {
  std::string out;
  for (const auto& [e, n] : table) out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

// The value named `name`, or InputError "unknown WHAT 'name' (known: ...)".
template <class E, std::size_t N>
E from_name(const NameTable<E, N>& table, const std::string& name, const std::string& what) {
  for (const auto& [e, n] : table)
    if (name == n) return e;
  throw InputError("unknown " + what + " '" + name + "' (known: " + names(table) + ")");
}

template <class E, std::size_t N>
const char* name_in(const NameTable<E, N>& table, E value) {
  for (const auto& [e, n] : table)
    if (e == value) return n;
  return "?";
}

}  // namespace cellproj
