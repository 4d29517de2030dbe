// The images of a point on the torus [lo, lo + side)^N that a search with a given reach must visit (the
// periodic RDF), and the minimum image of a difference (every periodic distance). Private (not installed).
#pragma once

#include <cmath>

namespace dfvn {

// d - side round(d / side): the shortest of the differences d + k side.
inline double minimum_image(double d, double side) { return d - side * std::nearbyint(d / side); }

namespace periodic_detail {

// Axes a.. of the depth-first walk: y holds x shifted on the axes before a, gap2 the squared distance
// of that partial image to the box.
template <int N, typename Reach, typename Visit>
void visit_images(double* y, const double* x, double lo, double side, int a, double gap2, bool moved,
                  const Reach& reach, const Visit& visit) {
  if (a == N) {
    if (moved) visit(static_cast<const double*>(y));
    return;
  }
  visit_images<N>(y, x, lo, side, a + 1, gap2, moved, reach, visit);
  // Shifted up by one side, the image lies x_a - lo beyond the box's upper face; shifted down,
  // lo + side - x_a below its lower face.
  const double gaps[2] = {x[a] - lo, lo + side - x[a]};
  const double shifts[2] = {side, -side};
  for (int k = 0; k < 2; ++k) {
    const double r = reach();
    if (!(gap2 + gaps[k] * gaps[k] < r * r)) continue;
    y[a] = x[a] + shifts[k];
    visit_images<N>(y, x, lo, side, a + 1, gap2 + gaps[k] * gaps[k], true, reach, visit);
    y[a] = x[a];
  }
}

}  // namespace periodic_detail

// Calls visit(y) for every image y = x + side s, s in {-1, 0, 1}^N without s = 0, whose distance to the
// box [lo, lo + side]^N is below reach(): only those can hold a point closer than the reach. reach()
// is asked again before each image, so a search whose nearest distance shrinks prunes more.
template <int N, typename Reach, typename Visit>
void for_each_periodic_image(const double* x, double lo, double side, const Reach& reach, const Visit& visit) {
  double y[N];
  for (int a = 0; a < N; ++a) y[a] = x[a];
  periodic_detail::visit_images<N>(y, x, lo, side, 0, 0.0, false, reach, visit);
}

}  // namespace dfvn
