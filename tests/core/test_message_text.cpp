#include "dfvn/core/message_text.hpp"

#include <gtest/gtest.h>

#include <string>

#include "dfvn/core/parallel.hpp"

namespace dfvn {
namespace {

TEST(MessageText, QuotedEscapesNonPrintableBytes) {
  EXPECT_EQ(quote_for_message("abc"), "'abc'");
  EXPECT_EQ(quote_for_message(""), "''");
  EXPECT_EQ(quote_for_message(std::string("a\0b", 3)), "'a\\0b'");
  EXPECT_EQ(quote_for_message("\x1B[2J\n\t\r"), "'\\x1B[2J\\n\\t\\r'");
  EXPECT_EQ(quote_for_message("\xEF\xBB\xBF" "1"), "'\\xEF\\xBB\\xBF1'");
  EXPECT_EQ(quote_for_message("a\\b"), "'a\\\\b'");
}

TEST(MessageText, QuotedShortensToTheLimitWithoutSplittingAnEscape) {
  EXPECT_EQ(quote_for_message(std::string(40, 'x')), "'" + std::string(40, 'x') + "'");
  EXPECT_EQ(quote_for_message(std::string(41, 'x')), "'" + std::string(40, 'x') + "...' (41 bytes)");
  // 39 characters, then an escape of 4 that would pass the limit: cut before it.
  EXPECT_EQ(quote_for_message(std::string(39, 'x') + "\x01" + "yy"), "'" + std::string(39, 'x') + "...' (42 bytes)");
  EXPECT_EQ(quote_for_message(std::string(1000, 'x'), 5), "'xxxxx...' (1000 bytes)");
}

TEST(MessageText, EscapeBytesKeepsBackslashesWhenAsked) {
  EXPECT_EQ(escape_bytes("a\\n\nb", false), "a\\n\\nb");
  EXPECT_EQ(escape_bytes("a\\b", true), "a\\\\b");
}

TEST(MessageText, ByteSizesUseAUnitThatShowsThem) {
  EXPECT_EQ(byte_size(0), "0 B");
  EXPECT_EQ(byte_size(1023), "1023 B");
  EXPECT_EQ(byte_size(1024), "1.00 KiB");
  EXPECT_EQ(byte_size(0.001 * (1 << 30)), "1.02 MiB");  // --max-memory 0.001 printed "0.0 GiB"
  EXPECT_EQ(byte_size(6.0 * (1 << 20)), "6.00 MiB");
  EXPECT_EQ(byte_size(300.0 * (1 << 30)), "300 GiB");
  EXPECT_EQ(byte_size(1.5 * 1152921504606846976.0), "1.50 EiB");
  EXPECT_EQ(byte_size(1e30), "8.67e+11 EiB");
}

TEST(ThreadCount, RangeIsZeroOrUpToFourTimesTheCores) {
  EXPECT_GE(max_thread_count(), 4);
  EXPECT_LE(max_thread_count(), kMaxThreads);
  EXPECT_NO_THROW(check_thread_count(0));
  EXPECT_NO_THROW(check_thread_count(max_thread_count()));
  EXPECT_THROW(check_thread_count(-1), std::invalid_argument);
  EXPECT_THROW(check_thread_count(max_thread_count() + 1), std::invalid_argument);
  EXPECT_THROW(check_thread_count(100000), std::invalid_argument);
  EXPECT_EQ(resolve_threads(3), 3);
  EXPECT_GE(resolve_threads(0), 1);
}

}  // namespace
}  // namespace dfvn
