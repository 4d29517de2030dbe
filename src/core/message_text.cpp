#include "dfvn/core/message_text.hpp"

#include <cmath>
#include <iterator>

#include <fmt/format.h>

namespace dfvn {

namespace {

void append_escaped(std::string& out, unsigned char c, bool escape_backslash) {
  switch (c) {
    case '\n': out += "\\n"; return;
    case '\t': out += "\\t"; return;
    case '\r': out += "\\r"; return;
    case '\0': out += "\\0"; return;
    case '\\': out += escape_backslash ? "\\\\" : "\\"; return;
    default:
      if (c >= 0x20 && c < 0x7F)
        out += static_cast<char>(c);
      else
        fmt::format_to(std::back_inserter(out), "\\x{:02X}", c);
  }
}

}  // namespace

std::string escape_bytes(std::string_view text, bool escape_backslash) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) append_escaped(out, static_cast<unsigned char>(c), escape_backslash);
  return out;
}

std::string quote_for_message(std::string_view text, std::size_t max_chars) {
  std::string body;
  std::size_t used = 0;
  for (; used < text.size(); ++used) {
    std::string piece;
    if (text[used] == '\'')
      piece = "\\'";  // a quote inside the quotes is escaped: the text is quoted once, unambiguously
    else
      append_escaped(piece, static_cast<unsigned char>(text[used]), true);
    if (body.size() + piece.size() > max_chars) break;
    body += piece;
  }
  if (used == text.size()) return "'" + body + "'";
  return fmt::format("'{}...' ({} bytes)", body, text.size());
}

std::string byte_size(double bytes) {
  static constexpr const char* kUnits[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  constexpr int kLast = static_cast<int>(std::size(kUnits)) - 1;
  int unit = 0;
  while (unit < kLast && std::abs(bytes) >= 1024.0) {
    bytes /= 1024.0;
    ++unit;
  }
  if (unit == 0) return fmt::format("{:.0f} B", bytes);
  if (unit == kLast && bytes >= 1024.0) return fmt::format("{:.3g} EiB", bytes);
  const int decimals = bytes < 10.0 ? 2 : bytes < 100.0 ? 1 : 0;  // three significant digits
  return fmt::format("{:.{}f} {}", bytes, decimals, kUnits[unit]);
}

}  // namespace dfvn
