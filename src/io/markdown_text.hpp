// Markdown reports as plain text for a terminal: the reproductions write Markdown files (tables with
// <br> line breaks in cells, **bold**, `code`) and print the same report readable without a renderer.
#pragma once

#include <string>
#include <string_view>

namespace dfvn {

// Tables become aligned columns (a cell's <br> starts a new line within the cell; the |---| row becomes
// a rule under the header; rows with several lines are separated by a blank line); headings lose their
// #s and are underlined; ** and ` marks are removed. Other text is kept as it is.
std::string markdown_as_plain_text(std::string_view markdown);

}  // namespace dfvn
