// Bulk memory: huge-page-aligned zeroed pages for large blocks, vectors that do not fill what they size.
#include "dfvn/core/bulk_memory.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <numeric>
#include <string>

namespace dfvn {
namespace {

TEST(BulkMemory, MappedPagesStartOnAHugePageAndAreZero) {
  const std::size_t bytes = (std::size_t{5} << 20) + 123;  // not a multiple of any page
  auto* p = static_cast<unsigned char*>(map_pages(bytes));
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(p) % (std::uintptr_t{2} << 20), 0u);
  std::size_t nonzero = 0;
  for (std::size_t i = 0; i < bytes; ++i) nonzero += p[i] != 0;
  EXPECT_EQ(nonzero, 0u);
  p[0] = 1;
  p[bytes - 1] = 2;  // the last byte is writable
  release_pages(p, bytes);
  release_pages(nullptr, bytes);  // a no-op
}

// Below and above kBulkPagesFrom: the values written are the values read, through copies, moves,
// growth and shrinking.
TEST(BulkMemory, CoordinatesBehaveAsAVectorOfDoubles) {
  for (const std::size_t n : {std::size_t{10}, kBulkPagesFrom / sizeof(double) + 7}) {
    Coordinates a(n);
    std::iota(a.begin(), a.end(), 0.5);
    const Coordinates copy = a;
    EXPECT_EQ(copy, a);
    Coordinates moved = std::move(a);
    EXPECT_EQ(moved, copy);
    moved.push_back(-1.0);  // reallocates
    EXPECT_EQ(moved.back(), -1.0);
    EXPECT_EQ(moved[n - 1], static_cast<double>(n - 1) + 0.5);
    moved.resize(3);
    moved.shrink_to_fit();
    EXPECT_EQ(moved, (Coordinates{0.5, 1.5, 2.5}));
    EXPECT_EQ(Coordinates(n, 0.25)[n / 2], 0.25);  // an explicit value is still written
  }
}

// Large blocks get their own pages with huge-page advice; where the kernel uses transparent huge pages
// on advice ("madvise" or "always"), a touched 8 MB block is backed by them.
TEST(BulkMemory, LargeBlocksUseHugePagesWhereTheSystemOffersThem) {
  std::ifstream mode_file("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string mode;
  std::getline(mode_file, mode);
  if (mode.find("[never]") != std::string::npos || mode.empty()) GTEST_SKIP() << "transparent huge pages: " << mode;
  auto anon_huge_kb = [] {
    std::ifstream smaps("/proc/self/smaps_rollup");
    std::string key;
    long long kb = 0;
    while (smaps >> key) {
      if (key == "AnonHugePages:") {
        smaps >> kb;
        return kb;
      }
      smaps.ignore(1 << 20, '\n');
    }
    return -1LL;
  };
  const long long before = anon_huge_kb();
  if (before < 0) GTEST_SKIP() << "no AnonHugePages in /proc/self/smaps_rollup";
  Coordinates big((std::size_t{8} << 20) / sizeof(double));
  for (std::size_t i = 0; i < big.size(); i += 512) big[i] = 1.0;  // touch every 4 KB page
  const long long after = anon_huge_kb();
  // Where the kernel does not compact memory for advised regions, it may lack a free huge page at the
  // moment (fragmented memory) and the advice is moot; where it does, the advice must take effect.
  std::ifstream defrag_file("/sys/kernel/mm/transparent_hugepage/defrag");
  std::string defrag;
  std::getline(defrag_file, defrag);
  const bool compacts = defrag.find("[always]") != std::string::npos || defrag.find("madvise]") != std::string::npos;
  if (after == before && !compacts) GTEST_SKIP() << "no huge page was available (defrag: " << defrag << ")";
  EXPECT_GE(after - before, 2048) << "enabled: " << mode << ", defrag: " << defrag;
}

}  // namespace
}  // namespace dfvn
