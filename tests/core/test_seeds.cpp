// check_seed_range: issue 23, the third seed of --seed 2^64 - 2 --realizations 3 wrapped to 0.
#include "dfvn/core/seeds.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "dfvn/reproduce/cnj_study.hpp"
#include "dfvn/reproduce/integration.hpp"
#include "dfvn/reproduce/reproduce.hpp"

namespace dfvn {
namespace {

constexpr std::uint64_t kLargest = std::numeric_limits<std::uint64_t>::max();

TEST(SeedRange, TheLastSeedMayBeTwoToTheSixtyFourMinusOneNotMore) {
  EXPECT_NO_THROW(check_seed_range(kLargest, 1, "--seed", "--realizations"));
  EXPECT_NO_THROW(check_seed_range(kLargest - 2, 3, "--seed", "--realizations"));
  EXPECT_NO_THROW(check_seed_range(0, kLargest, "--seed", "--realizations"));
  try {
    check_seed_range(kLargest - 1, 3, "--seed", "--realizations");
    ADD_FAILURE() << "wrapped seeds accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "--seed 18446744073709551614 with --realizations 3 needs seeds up to 18446744073709551614 + 2, past "
                 "2^64 - 1 = 18446744073709551615; give --seed at most 18446744073709551613");
  }
  EXPECT_NO_THROW(check_seed_range(1, kLargest, "--seed", "--realizations"));  // seeds 1 .. 2^64 - 1
  EXPECT_THROW(check_seed_range(2, kLargest, "--seed", "--realizations"), std::invalid_argument);
}

// Every configuration that runs seeds s..s+R-1 refuses a range that wraps, naming its options.
TEST(SeedRange, EveryRepeatedRunChecksItsSeeds) {
  const auto message = [](const auto& config) -> std::string {
    try {
      config.validate();
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "accepted";
  };
  Table1Config table1;
  table1.seed = kLargest - 1;
  table1.realizations = 3;
  EXPECT_NE(message(table1).find("--seed 18446744073709551614 with --realizations 3"), std::string::npos) << message(table1);
  table1.realizations = 2;
  EXPECT_EQ(message(table1), "accepted");
  IntegrationConfig integration;
  integration.seed = kLargest;
  integration.realizations = 2;
  EXPECT_NE(message(integration).find("with --realizations 2"), std::string::npos) << message(integration);
  CnjStudyConfig study;
  study.seed = kLargest - 1;
  study.seeds = 3;
  EXPECT_NE(message(study).find("with --realizations 3"), std::string::npos) << message(study);
}

}  // namespace
}  // namespace dfvn
