// Wrappers of a noise basis that change where its functions are read, never what they are: a linear
// stretch (f_i(A x), issue 27 item 1), a slice of the basis one dimension up at a fixed last coordinate
// (time as an extra noise dimension, issue 25 item 2) and a lift onto a height field (f(x) =
// F(x, h(x)), the paper's Section 5.5, issue 27 item 2). Each is a composition of a C2 function with
// a smooth (C2 or linear) map, so the wrapped functions stay C2 and cross(grad f_i) stays exactly
// divergence-free; the gradients are exact by the chain rule. The field (field/dfvn_field.hpp) builds
// them from FieldOptions::transform and renormalises RMS |c|.
#pragma once

#include <cmath>
#include <memory>
#include <utility>

#include "dfvn/core/dimension.hpp"
#include "dfvn/noise/noise_functions.hpp"

namespace dfvn {

// n_i(A y) with A = I + (S - 1) u u^T, u a unit vector and S > 0: the noise S times faster along u,
// unchanged across it. grad = A^T (grad n_i)(A y) = A (grad n_i)(A y) (A is symmetric). The wavenumber is
// the inner basis's (the field keeps its scale s, so f_i(x) is the unstretched f_i at A x up to a
// constant factor). The amplitude is derived: cross(A g_1, ..., A g_{N-1}) = det(A) A^(-T) cross(g) =
// S A^(-1) c0, so E|c|^2 = S^2 (E|c0|^2 - (1 - S^-2) E(u . c0)^2) = (S^2 (N-1) + 1) / N when E[c0 c0^T] =
// I / N. That holds for every basis: a 2-tensor invariant under the cube's symmetries (the lattice
// bases) or under rotations (turning bands' two full frames) is a multiple of I. c scales as A^(N-1),
// so A_stretched = A ((S^2 (N-1) + 1) / N)^(-1 / (2 (N-1))).
template <int N>
class StretchedNoise final : public NoiseFunctions<N> {
 public:
  StretchedNoise(std::shared_ptr<const NoiseFunctions<N>> inner, const Vec<N>& unit_direction, double factor)
      : inner_(std::move(inner)), u_(unit_direction), s_minus_1_(factor - 1.0) {}

  Vec<N> apply(const Vec<N>& y) const { return y + (s_minus_1_ * u_.dot(y)) * u_; }

  NoiseSample<N, N - 1> evaluate(const Vec<N>& y) const override {
    NoiseSample<N, N - 1> out = inner_->evaluate(apply(y));
    for (auto& g : out.gradient) g = apply(g);
    return out;
  }
  double wavenumber() const override { return inner_->wavenumber(); }
  double amplitude() const override {
    const double s = s_minus_1_ + 1.0;
    return inner_->amplitude() * std::pow((s * s * (N - 1) + 1.0) / N, -0.5 / (N - 1));
  }

 private:
  std::shared_ptr<const NoiseFunctions<N>> inner_;
  Vec<N> u_;
  double s_minus_1_;
};

// The first N-1 functions of an (N+1)-dimensional basis at (y, w) with w fixed, and the first N
// components of their gradients: the slice of space-time at time w (in the inner basis's units).
// wavenumber() is that of the slice: for an isotropic basis E|grad_y n|^2 = N / (N+1) E|grad n|^2, so
// k_slice = k_{N+1} sqrt(N / (N+1)), and a frequency means the same number of cycles per unit length
// along x as without the slice. amplitude() is derived: for independent functions whose gradients have
// covariance v I (every basis, as above), E|cross|^2 = M! v^(M-1) for M-1 functions in M dimensions
// (Cauchy-Binet; only second moments enter). The inner amplitude A gives (N+1)! (A^2 v)^N = 1, the slice
// needs N! (A'^2 v)^(N-1) = 1: A' = A sqrt((N!)^(-1/(N-1)) / ((N+1)!)^(-1/N)). It does not depend on w.
template <int N>
class SlicedNoise final : public NoiseFunctions<N> {
 public:
  SlicedNoise(std::shared_ptr<const NoiseFunctions<N + 1>> inner, double w) : inner_(std::move(inner)), w_(w) {}

  NoiseSample<N, N - 1> evaluate(const Vec<N>& y) const override {
    Vec<N + 1> z;
    z.template head<N>() = y;
    z[N] = w_;
    const NoiseSample<N + 1, N> full = inner_->evaluate(z);
    NoiseSample<N, N - 1> out;
    for (int i = 0; i < N - 1; ++i) {
      out.value[i] = full.value[i];
      out.gradient[i] = full.gradient[i].template head<N>();
    }
    return out;
  }
  double wavenumber() const override { return slice_wavenumber(*inner_); }
  double amplitude() const override { return slice_amplitude(*inner_); }

  static double slice_amplitude(const NoiseFunctions<N + 1>& inner) {
    double n_factorial = 1.0;
    for (int k = 2; k <= N; ++k) n_factorial *= k;
    const double n1_factorial = n_factorial * (N + 1);
    return inner.amplitude() * std::sqrt(std::pow(n_factorial, -1.0 / (N - 1)) / std::pow(n1_factorial, -1.0 / N));
  }
  static double slice_wavenumber(const NoiseFunctions<N + 1>& inner) {
    return inner.wavenumber() * std::sqrt(static_cast<double>(N) / (N + 1));
  }

 private:
  std::shared_ptr<const NoiseFunctions<N + 1>> inner_;
  double w_;
};

// A height field h: R^2 -> R with its gradient, C2 (field/height_field.hpp says which ones exist).
class HeightField {
 public:
  virtual ~HeightField() = default;
  // h(x) and grad h(x) at x in the field's length units.
  virtual double height(const Vec<2>& x, Vec<2>& gradient) const = 0;
};

// The 2D lift of a 3D basis onto the surface z = h(x) (the paper's Section 5.5): in the basis's units
// y = s x, n(y) = F(y, s h(y / s)) with F the first function of the 3D basis, so that the field's
// f(x) = (A / s) n(s x) = (A / s) F(s x, s h(x)) is F lifted in the field's own length units.
// grad n(y) = grad_xy F + dF/dz grad h(y / s). With h = 0 this is SlicedNoise<2> at w = 0, bit for bit
// (the same wavenumber and the same arithmetic: h = 0 adds an exact 0). The vertical ramp of the paper's
// Figure 9 is F + r z (r in the basis's units): on a slope it adds r grad h to every gradient, a steady
// motion along the contour lines of h, and nothing where the surface is flat.
class LiftedNoise final : public NoiseFunctions<2> {
 public:
  LiftedNoise(std::shared_ptr<const NoiseFunctions<3>> inner, std::shared_ptr<const HeightField> height, double scale,
              double ramp = 0.0)
      : inner_(std::move(inner)), height_(std::move(height)), scale_(scale), ramp_(ramp) {}

  NoiseSample<2, 1> evaluate(const Vec<2>& y) const override {
    Vec<2> grad_h;
    const double h = height_->height(y / scale_, grad_h);
    const NoiseSample<3, 2> full = inner_->evaluate(Vec<3>(y[0], y[1], scale_ * h));
    NoiseSample<2, 1> out;
    // The vertical ramp adds r z to F: dF/dz + r multiplies grad h, and r s h is added to the value.
    const double dz = full.gradient[0][2] + ramp_;
    out.value[0] = full.value[0] + (ramp_ == 0.0 ? 0.0 : ramp_ * scale_ * h);
    out.gradient[0] = full.gradient[0].head<2>() + dz * grad_h;
    return out;
  }
  double wavenumber() const override { return SlicedNoise<2>::slice_wavenumber(*inner_); }
  // The flat surface's (h = 0, the slice's): a slope raises the speed (the paper's Figure 9).
  double amplitude() const override { return SlicedNoise<2>::slice_amplitude(*inner_); }

 private:
  std::shared_ptr<const NoiseFunctions<3>> inner_;
  std::shared_ptr<const HeightField> height_;
  double scale_;
  double ramp_;
};

}  // namespace dfvn
