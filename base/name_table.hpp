#pragma once
// The names of an enum's values on the command line and in files, from one table per enum (an
// array of {value, name} pairs): parsing (an InputError listing the known names), printing, and
// the list for help texts.
#include <iterator>
#include <string>
#include <type_traits>
#include <utility>

#include "base/error.hpp"

namespace cellproj {

// "a, b, c"
template <class Table>
std::string names(const Table& table) {
  std::string out;
  for (const auto& [e, n] : table) out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

// The value named `name`, or InputError "unknown WHAT 'name' (known: ...)".
template <class Table>
auto from_name(const Table& table, const std::string& name, const std::string& what)
    -> std::decay_t<decltype(std::begin(table)->first)> {
  for (const auto& [e, n] : table)
    if (name == n) return e;
  throw InputError("unknown " + what + " '" + name + "' (known: " + names(table) + ")");
}

template <class Table, class E>
const char* name_in(const Table& table, E value) {
  for (const auto& [e, n] : table)
    if (e == value) return n;
  return "?";
}

}  // namespace cellproj
