// Perlin's quintic fade s(u) = 6u^5 - 15u^4 + 10u^3 (Perlin 2002): s(0) = 0, s(1) = 1 and s', s''
// vanish at both ends, so noise interpolated with it between lattice knots is C2.
#pragma once

namespace dfvn {

inline double quintic_fade(double u) { return u * u * u * (u * (6.0 * u - 15.0) + 10.0); }

// s'(u) = 30 u^2 (u - 1)^2.
inline double quintic_fade_slope(double u) {
  const double v = u * (u - 1.0);
  return 30.0 * v * v;
}

}  // namespace dfvn
