#pragma once
// A number given as text (an option, a keyword, a scene's word), taken only when the whole text
// is one: "12x", "" and "1 2" are not numbers. The callers say what they expected.
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace cellproj {

template <class T>
std::optional<T> whole_number(const std::string& text) {
  static_assert(std::is_same_v<T, int> || std::is_same_v<T, double>);
  std::size_t used = 0;
  T value{};
  try {
    if constexpr (std::is_same_v<T, int>)
      value = std::stoi(text, &used);
    else
      value = std::stod(text, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (text.empty() || used != text.size()) return std::nullopt;
  return value;
}

}  // namespace cellproj
