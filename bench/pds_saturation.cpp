// The saturation density of Poisson disk sampling (sampling/poisson_disk.hpp's
// poisson_disk_saturation_density and its boundary term): for each dimension, sets run until their
// queue empties at the radius where the torus' density D gives about `points` points, in the unit torus
// (D = points * r^N / volume) and in the unit cube and ball (the excess over D V / r^N, per r times the
// boundary's area over the volume, 2N / side for both: the boundary term B of the library), over seeds.
//   pds_saturation [points] [seeds] [candidates] [kinds]   (default 131072 5 30 torus,cube,ball; 2D runs
//   16x the points)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "dfvn/core/domain.hpp"
#include "dfvn/core/stopwatch.hpp"
#include "dfvn/sampling/poisson_disk.hpp"

int main(int argc, char** argv) {
  const double points = argc > 1 ? std::atof(argv[1]) : 131072.0;
  const int seeds = argc > 2 ? std::atoi(argv[2]) : 5;
  const int candidates = argc > 3 ? std::atoi(argv[3]) : 30;
  if (!(points >= 16) || seeds < 1 || candidates < 1) {
    std::fprintf(stderr, "pds_saturation: usage: pds_saturation [points >= 16] [seeds >= 1] [candidates >= 1]\n");
    return 2;
  }
  const std::string kinds = argc > 4 ? argv[4] : "torus,cube,ball";
  std::printf("dim,domain,points_asked,seed,points,radius,density,boundary_term,seconds\n");
  for (int n = 2; n <= 8; ++n)
    for (const char* kind_name : {"torus", "cube", "ball"}) {
      if (kinds.find(kind_name) == std::string::npos) continue;
      const dfvn::DomainKind kind = dfvn::parse_domain_kind(kind_name);
    // The radius for `points` by the library's table (the measured D is points * r^N / volume whatever
    // the radius; the table's values came from a first pass of this program).
    const double guess = dfvn::poisson_disk_saturation_density(n);
    dfvn::PoissonDiskOptions options;
    options.domain = dfvn::Domain::unit(kind);
    options.candidates = candidates;
    const double asked = n == 2 ? 16 * points : points;  // 2D runs fast
    options.radius = std::min(0.45, std::pow(guess * options.domain.measure(n) / asked, 1.0 / n));
    std::vector<double> densities;
    for (int s = 1; s <= seeds; ++s) {
      const dfvn::Stopwatch watch;
      const dfvn::PoissonDiskResult r = dfvn::poisson_disk(n, options, static_cast<std::uint64_t>(s), 0);
      const double volume = options.domain.measure(n);
      const double d = static_cast<double>(r.points.size()) * std::pow(options.radius, n) / volume;
      // points = D V / r^N (1 + B (2N / side) r): B from the torus' D.
      const double boundary = kind == dfvn::DomainKind::torus
                                  ? 0.0
                                  : (d / dfvn::poisson_disk_saturation_density(n) - 1.0) / (2.0 * n * options.radius);
      densities.push_back(kind == dfvn::DomainKind::torus ? d : boundary);
      std::printf("%d,%s,%.0f,%d,%zu,%.17g,%.9g,%.9g,%.3f\n", n, kind_name, asked, s, r.points.size(), options.radius, d,
                  boundary, watch.seconds());
      std::fflush(stdout);
    }
    std::sort(densities.begin(), densities.end());
    std::fprintf(stderr, "%dD %s: median %s = %.6g (min %.6g, max %.6g)\n", n, kind_name,
                 kind == dfvn::DomainKind::torus ? "D" : "B", densities[densities.size() / 2], densities.front(),
                 densities.back());
  }
  return 0;
}
