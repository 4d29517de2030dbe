// Text for error messages: user input echoed safely, sizes in readable units. Every message the
// tool prints is one line, so what it quotes must not carry newlines, escape bytes or megabytes.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace dfvn {

// Bytes outside printable ASCII as C escapes (\n, \t, \r, \0, \xHH), so that control bytes cannot
// reach the terminal, a NUL cannot cut the message, and invisible bytes (a UTF-8 byte order mark,
// EF BB BF) show. With `escape_backslash`, '\' becomes "\\" so the escapes are unambiguous.
std::string escape_bytes(std::string_view text, bool escape_backslash = true);

// `text` for a message: in single quotes, escaped (a quote in it as \'), and cut to about max_chars characters with
// "..." and the full length in bytes, e.g. 'aaaaaaaa...' (1048576 bytes).
inline constexpr std::size_t kMaxEchoChars = 40;
inline constexpr std::size_t kMaxPathEchoChars = 160;  // paths are the user's own and worth showing whole
std::string quote_for_message(std::string_view text, std::size_t max_chars = kMaxEchoChars);

// A size in bytes with the binary unit that shows it: "512 B", "10.7 MiB", "1.50 EiB".
std::string byte_size(double bytes);

}  // namespace dfvn
