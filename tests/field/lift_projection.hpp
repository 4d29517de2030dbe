// The lifted field's defining identity, shared by test_field_lift (plane, bump) and test_field_lift_npy:
// on the surface z = h(x), the xy-projection of grad F x grad(z - h) (F the 3D noise in field units) is the
// 2D field c of F(x, h(x)).
#pragma once

#include <algorithm>

#include <Eigen/Geometry>

#include "dfvn/field/dfvn_field.hpp"
#include "test_support.hpp"

namespace dfvn::testing {

// The largest relative |P(grad F x grad(z - h)) - c| / |c| over 2000 random points in [lo, hi]^2 (field seed 11,
// point seed 9).
inline double largest_lift_projection_error(NoiseBasis basis, const FieldOptions& options, double lo, double hi) {
  const DfvnField<2> field(11, options);
  const auto noise3 = make_noise_functions<3>(basis, 11);
  const auto height = make_height_field(options.transform.lift);
  const double s = field.scale(), a = field.amplitude();
  double worst = 0.0;
  for (std::uint64_t k = 0; k < 2000; ++k) {
    const Vec<2> x = random_point<2>(9, k, lo, hi);
    Vec<2> grad_h;
    const double h = height->height(x, grad_h);
    const Vec<3> grad_f = a * noise3->evaluate(Vec<3>(s * x[0], s * x[1], s * h)).gradient[0];  // grad F, field units
    const Vec<3> projected = grad_f.cross(Vec<3>(-grad_h[0], -grad_h[1], 1.0));      // grad F x grad(z - h)
    const Vec<2> c = field.velocity(x);
    worst = std::max(worst, (projected.head<2>() - c).norm() / std::max(1e-300, c.norm()));
  }
  return worst;
}

}  // namespace dfvn::testing
