#pragma once
// The one count of characters in a UTF-8 text that libio's layouts estimate widths from (text
// tables, plot legends, drawing annotation), private to libio.
#include <cstddef>
#include <string_view>

namespace gearkit::io::detail {

/// Characters of a UTF-8 string, a multi-byte sequence counting once (right for the symbols
/// used: °, α, ε, µ).
inline std::size_t glyphs(std::string_view s) {
  std::size_t n = 0;
  for (unsigned char c : s) n += (c & 0xC0u) != 0x80u;
  return n;
}

}  // namespace gearkit::io::detail
