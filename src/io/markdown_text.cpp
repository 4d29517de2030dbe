#include "dfvn/io/markdown_text.hpp"

#include <algorithm>
#include <vector>

namespace dfvn {

namespace {

// Drops ** and the backticks of code spans; what is inside a code span is kept as written.
std::string without_marks(std::string_view text) {
  std::string out;
  bool code = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '`') {
      code = !code;
    } else if (!code && text.substr(i, 2) == "**") {
      ++i;
    } else {
      out += text[i];
    }
  }
  return out;
}

std::string trimmed(std::string_view text) {
  const std::size_t first = text.find_first_not_of(' ');
  if (first == std::string_view::npos) return "";
  return std::string(text.substr(first, text.find_last_not_of(' ') - first + 1));
}

// Width on a terminal: one column per UTF-8 code point (the reports hold no wide characters).
std::size_t display_width(std::string_view text) {
  return static_cast<std::size_t>(std::count_if(text.begin(), text.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

// "| a | b<br>c |" -> cells, each a list of lines.
std::vector<std::vector<std::string>> table_cells(std::string_view line) {
  std::vector<std::vector<std::string>> cells;
  line.remove_prefix(1);  // the leading '|'
  if (!line.empty() && line.back() == '|') line.remove_suffix(1);
  std::size_t start = 0;
  while (true) {
    const std::size_t bar = line.find('|', start);
    std::string_view cell = line.substr(start, bar == std::string_view::npos ? std::string_view::npos : bar - start);
    std::vector<std::string> lines;
    std::size_t from = 0;
    while (true) {
      const std::size_t br = cell.find("<br>", from);
      lines.push_back(trimmed(without_marks(cell.substr(from, br == std::string_view::npos ? std::string_view::npos : br - from))));
      if (br == std::string_view::npos) break;
      from = br + 4;
    }
    cells.push_back(std::move(lines));
    if (bar == std::string_view::npos) break;
    start = bar + 1;
  }
  return cells;
}

bool is_rule(const std::vector<std::vector<std::string>>& cells) {
  for (const auto& cell : cells)
    if (cell.size() != 1 || cell.front().empty() || cell.front().find_first_not_of("-:") != std::string::npos) return false;
  return true;
}

std::string render_table(const std::vector<std::string_view>& lines) {
  std::vector<std::vector<std::vector<std::string>>> rows;
  std::size_t rule_after = 0;  // rows above the |---| line (the header), 0 if none
  for (std::string_view line : lines) {
    auto cells = table_cells(line);
    if (is_rule(cells)) {
      rule_after = rows.size();
    } else {
      rows.push_back(std::move(cells));
    }
  }
  std::vector<std::size_t> widths;
  bool multi_line = false;
  for (const auto& row : rows)
    for (std::size_t c = 0; c < row.size(); ++c) {
      if (widths.size() <= c) widths.push_back(0);
      for (const auto& text : row[c]) widths[c] = std::max(widths[c], display_width(text));
      multi_line = multi_line || row[c].size() > 1;
    }
  std::string out;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    if (multi_line && r > rule_after && r > 0) out += '\n';
    std::size_t height = 0;
    for (const auto& cell : rows[r]) height = std::max(height, cell.size());
    for (std::size_t k = 0; k < height; ++k) {
      std::string line;
      for (std::size_t c = 0; c < rows[r].size(); ++c) {
        const std::string text = k < rows[r][c].size() ? rows[r][c][k] : "";
        line += text;
        if (c + 1 < rows[r].size()) line += std::string(widths[c] - display_width(text) + 2, ' ');
      }
      const std::size_t last = line.find_last_not_of(' ');
      out += (last == std::string::npos ? std::string() : line.substr(0, last + 1)) + '\n';
    }
    if (rule_after > 0 && r + 1 == rule_after) {
      std::size_t total = 0;
      for (std::size_t w : widths) total += w + 2;
      out += std::string(total - 2, '-') + '\n';
    }
  }
  return out;
}

}  // namespace

std::string markdown_as_plain_text(std::string_view markdown) {
  std::string out;
  std::vector<std::string_view> table;
  std::size_t start = 0;
  while (start < markdown.size()) {
    std::size_t end = markdown.find('\n', start);
    if (end == std::string_view::npos) end = markdown.size();
    const std::string_view line = markdown.substr(start, end - start);
    start = end + 1;
    if (!line.empty() && line.front() == '|') {
      table.push_back(line);
      continue;
    }
    if (!table.empty()) {
      out += render_table(table);
      table.clear();
    }
    const std::size_t hashes = line.find_first_not_of('#');
    if (hashes > 0 && hashes != std::string_view::npos && line[hashes] == ' ') {
      const std::string title = without_marks(line.substr(hashes + 1));
      out += title + '\n' + std::string(display_width(title), hashes == 1 ? '=' : '-') + '\n';
    } else {
      out += without_marks(line) + '\n';
    }
  }
  if (!table.empty()) out += render_table(table);
  return out;
}

}  // namespace dfvn
