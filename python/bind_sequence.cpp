// dfvn._core._sequence: points [start, start + count) of the Sobol, Halton and uniform random sequences,
// for the engines dfvn.Sobol, dfvn.Halton and dfvn.Random (python/dfvn/qmc.py), whose random(n) calls
// continue where the last one stopped and whose fast_forward(k) skips k points, as SciPy's do.
//
// Every point of the three is a function of its index alone, and the library computes any range of
// them with the bits of the whole set's rows (sobol_points_range, sobol_points_64, halton_points_range,
// uniform_random_points_range): from point 0 they are the points of `dfvn-sample --points`. Nothing is
// zero-filled or copied: Sobol writes into the NumPy array itself (sobol_points_into), the others' library
// arrays are handed to NumPy (array_owning).
#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/pybind11.h>

#include "dfvn/sampling/halton.hpp"
#include "dfvn/sampling/jitter.hpp"
#include "dfvn/sampling/sobol.hpp"
#include "checked_def.hpp"
#include "numpy_points.hpp"

namespace dfvn::python {

namespace {

// `digits`: Sobol's 32 (at most 2^32 points, `dfvn-sample`'s sequence) or 64 (SciPy's bits 33..64).
py::array_t<double> sequence(const std::string& method, int d, std::uint64_t start, std::uint64_t count,
                             std::uint64_t seed, bool scramble, int digits, int threads) {
  if (d < 1) throw py::value_error("d must be at least 1, got " + std::to_string(d));
  if (method != "sobol" && method != "halton" && method != "random")
    throw py::value_error("no sequence '" + method + "' (allowed: sobol, halton, random)");
  if (method == "sobol" && digits != 32 && digits != 64)
    throw py::value_error("Sobol digits must be 32 or 64, got " + std::to_string(digits));
  const Box unit{0.0, 1.0};
  if (method == "sobol" && digits == 32) {
    // Straight into a NumPy array (no zero fill): NumPy's allocator reuses the memory of freed arrays,
    // which warm loops of random(n) calls meet (a new library array would be fresh pages from 4 MB up).
    py::array_t<double> out = new_array(count, static_cast<std::size_t>(d));
    double* data = out.mutable_data();
    {
      py::gil_scoped_release unlocked;
      sobol_points_into(d, start, count, unit, scramble ? Scramble::owen : Scramble::none, seed, threads, data);
    }
    return out;
  }
  PointSet points;
  {
    py::gil_scoped_release unlocked;
    if (method == "sobol")
      points = sobol_points_64(d, start, count, unit, scramble ? Scramble::owen : Scramble::none, seed, threads);
    else if (method == "halton")
      points = halton_points_range(d, start, count, unit, scramble, seed, threads);
    else
      points = uniform_random_points_range(d, start, count, unit, seed, threads);
  }
  return array_owning(std::move(points.coordinates), count, static_cast<std::size_t>(d));
}

}  // namespace

void bind_sequence(py::module_& module) {
  using namespace pybind11::literals;
  def_checked(module, "_sequence", &sequence, "method"_a, "d"_a, "start"_a, "count"_a, "seed"_a, "scramble"_a,
              "digits"_a = 32, "threads"_a = 0,
             "Internal: points [start, start + count) of 'sobol', 'halton' or 'random' in [0,1)^d (dfvn.Sobol etc.).");
  module.attr("_sobol_max_dimensions") = kSobolMaxDimensions;
  module.attr("_halton_max_dimensions") = kHaltonMaxDimensions;
  // The table as SciPy ships it (scipy/stats/_sobol_direction_numbers.npz: poly, the primitive
  // polynomial with its leading and trailing terms, and vinit, m_1..m_s padded with zeros), for
  // tests/python/test_sobol_table.py.
  module.def("_joe_kuo_table", [] {
    const std::vector<JoeKuoRow> rows = joe_kuo_rows(kSobolMaxDimensions);
    const std::size_t width = rows.front().initial.size();
    py::array_t<std::int64_t> poly(static_cast<py::ssize_t>(rows.size()));
    py::array_t<std::int64_t> vinit({static_cast<py::ssize_t>(rows.size()), static_cast<py::ssize_t>(width)});
    auto p = poly.mutable_unchecked<1>();
    auto v = vinit.mutable_unchecked<2>();
    for (std::size_t d = 0; d < rows.size(); ++d) {
      const JoeKuoRow& row = rows[d];
      p(static_cast<py::ssize_t>(d)) = (std::int64_t{1} << row.degree) | (std::int64_t{row.coefficients} << 1) | 1;
      // SciPy gives dimension 1 (van der Corput, degree 0) the single m_1 = 1.
      const auto count = static_cast<std::size_t>(std::max(row.degree, 1));
      for (std::size_t k = 0; k < width; ++k)
        v(static_cast<py::ssize_t>(d), static_cast<py::ssize_t>(k)) = k >= count ? 0 : d == 0 ? 1 : row.initial[k];
    }
    return py::make_tuple(poly, vinit);
  }, "Internal: the compiled-in Joe-Kuo table in SciPy's form (poly, vinit).");
}

}  // namespace dfvn::python
