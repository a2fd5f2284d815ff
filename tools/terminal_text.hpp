#pragma once
// Text for the terminal: the library's words for its settings spelled as options, and no raw
// bytes of a garbled file (a reader's "unknown keyword" of binary data) sent to a terminal.
#include <cstdio>
#include <string>

#include "render/settings_table.hpp"

namespace cellproj {

// `s` with control characters (but newline and tab) and bytes that are not part of valid UTF-8
// written as \xNN; UTF-8 (a file name in any script) passes unchanged.
inline std::string printable(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
    bool ok = n > 0 && i + n <= s.size();
    for (std::size_t k = 1; ok && k < n; ++k) ok = (static_cast<unsigned char>(s[i + k]) >> 6) == 0x2;
    if (ok && n == 1 && ((c < 0x20 && c != '\n' && c != '\t') || c == 0x7F)) ok = false;
    if (!ok) {
      char hex[5];
      std::snprintf(hex, sizeof hex, "\\x%02X", c);
      out += hex;
      ++i;
      continue;
    }
    out.append(s, i, n);
    i += n;
  }
  return out;
}

// A library message as the command line says it: setting 'table-size' as --table-size, printable.
inline std::string cli_words(const std::string& message) { return printable(spell_settings(message, "--", "")); }

// "cellproj: warning: ..." on stderr.
inline void warn(const std::string& warning) {
  std::fprintf(stderr, "cellproj: warning: %s\n", cli_words(warning).c_str());
}

}  // namespace cellproj
