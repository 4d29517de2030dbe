// The index ranges a streamed run makes its slabs from (issue 28): rows first .. first + count - 1 of
// every index-addressable generator are the whole set's rows, bit for bit, including ranges that start
// and end inside Sobol's 4096-point blocks and CNJ ranges on the torus and in the cube.
#include <gtest/gtest.h>

#include <cstring>

#include "dfvn/sampling/curl_noise_jitter.hpp"
#include "dfvn/sampling/jitter.hpp"
#include "dfvn/sampling/sobol.hpp"

namespace dfvn {
namespace {

// The rows [first, first + count) of `whole` are `part`'s bytes.
void expect_rows(const PointSet& whole, const PointSet& part, std::uint64_t first, std::uint64_t count) {
  ASSERT_EQ(part.size(), count);
  ASSERT_EQ(part.dimension, whole.dimension);
  EXPECT_EQ(std::memcmp(whole.point(first), part.coordinates.data(), count * whole.dimension * sizeof(double)), 0)
      << "rows " << first << " .. " << first + count - 1;
}

TEST(SamplingRanges, SobolRowsAcrossBlocks) {
  const Box box{0.0, 1.5};
  // Owen on AVX2: 32 points at a time from multiples of 32, a range's points before and after them one
  // by one. On SSE2 2D and 3D take the batched kernel (batches of 8 from a range's first point), 5D the
  // per-point one and 20D the one for any dimension.
  for (int dim : {2, 3, 5, 20})
    for (Scramble scramble : {Scramble::owen, Scramble::none}) {
      const PointSet whole = sobol_points(dim, 10000, box, scramble, 7, 2);
      for (auto [first, count] : {std::pair<std::uint64_t, std::uint64_t>{0, 10000}, {1, 4095}, {4000, 200},
                                  {4096, 4096}, {9999, 1}, {3, 9000}, {5, 13}})
        expect_rows(whole, sobol_points_range(dim, first, count, box, scramble, 7, 1), first, count);
    }
}

TEST(SamplingRanges, RandomAndJitterRows) {
  const Box box{0.0, 1.0};
  const PointSet random = uniform_random_points(3, 1000, box, 4, 2);
  expect_rows(random, uniform_random_points_range(3, 117, 500, box, 4, 1), 117, 500);
  const LatticeSpec lattice{4, 5, Protocol::paper};
  const PointSet jitter = jittered_lattice(lattice, 9, 2);
  expect_rows(jitter, jittered_lattice_range(lattice, jitter_half_width(lattice), 125, 250, 9, 1), 125, 250);
}

TEST(SamplingRanges, CnjRowsOnTheTorusAndInTheCube) {
  const LatticeSpec lattice{3, 6, Protocol::paper};
  for (DomainKind domain : {DomainKind::torus, DomainKind::cube}) {
    CnjOptions options;
    options.domain = domain;
    const CnjResult whole = curl_noise_jitter(lattice, options, 3, 2);
    const CnjResult part = curl_noise_jitter_range(lattice, options, 3, 72, 108, 1);
    expect_rows(whole.points, part.points, 72, 108);
    ASSERT_EQ(part.displacements.size(), 108u * 3);
    EXPECT_EQ(std::memcmp(whole.displacements.data() + 72 * 3, part.displacements.data(), 108 * 3 * sizeof(double)), 0);
    EXPECT_EQ(part.trace_time, whole.trace_time);
  }
  CnjOptions ball;
  ball.domain = DomainKind::ball;
  EXPECT_THROW(curl_noise_jitter_range(lattice, ball, 3, 0, 10, 1), std::invalid_argument);
}

}  // namespace
}  // namespace dfvn
