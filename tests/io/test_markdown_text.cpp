// markdown_as_plain_text: what `reproduce` prints to a terminal.
#include "dfvn/io/markdown_text.hpp"

#include <gtest/gtest.h>

namespace dfvn {
namespace {

TEST(MarkdownAsPlainText, TablesBecomeAlignedColumnsWithCellLinesForBr) {
  const std::string md =
      "# Title\n\nSome **bold** and `code`.\n\n| n | cell |\n| --- | --- |\n| 3 | a<br>bb |\n| 10 | ccc ± d |\ntail\n";
  const std::string expected =
      "Title\n=====\n\nSome bold and code.\n\n"
      "n   cell\n"
      "-----------\n"
      "3   a\n"
      "    bb\n"
      "\n"
      "10  ccc ± d\n"
      "tail\n";
  EXPECT_EQ(markdown_as_plain_text(md), expected);
}

TEST(MarkdownAsPlainText, SingleLineRowsNeedNoBlankLinesAndHeadingsOfLevelTwoUseDashes) {
  const std::string md = "## Reading\n| a | b |\n| --- | --- |\n| 1 | 2 |\n| 3 | 4 |";
  EXPECT_EQ(markdown_as_plain_text(md), "Reading\n-------\na  b\n----\n1  2\n3  4\n");
}

TEST(MarkdownAsPlainText, CodeSpansKeepWhatTheyHold) {
  EXPECT_EQ(markdown_as_plain_text("**wrap**: `(a - b)**2` on uint8\n"), "wrap: (a - b)**2 on uint8\n");
}

TEST(MarkdownAsPlainText, TextWithoutMarkdownIsKept) {
  EXPECT_EQ(markdown_as_plain_text("plain line\n\n- item 7 * 3\n"), "plain line\n\n- item 7 * 3\n");
}

}  // namespace
}  // namespace dfvn
