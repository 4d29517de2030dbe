// NumPy arrays in and out of libdfvn: point sets are (points, N) float64 arrays in C order.
#pragma once

#include <cstddef>
#include <vector>

#include <pybind11/numpy.h>

namespace dfvn::python {

namespace py = pybind11;

// A point array as the library reads it. A float64 C-contiguous array is used in place; anything
// else NumPy can convert (float32, Fortran order, strided views, nested lists) is converted once.
using PointArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

// Rows of a (points, N) array, borrowed from the array (which must outlive it).
struct PointRows {
  const double* data = nullptr;
  std::size_t rows = 0;
  int dimension = 0;
};

// Checks that `points` is (points, N) with N in [min_dimension, max_dimension] (a 1-D array is N = 1
// when min_dimension is 1) and that it has at least `min_rows` rows; throws py::value_error saying what
// was wrong and what is allowed.
PointRows point_rows(const PointArray& points, int min_dimension, int max_dimension, std::size_t min_rows = 0);

// A new (rows, cols) float64 array to be filled.
py::array_t<double> new_array(std::size_t rows, std::size_t cols);

// A (rows, cols) float64 array that takes over `values` (rows * cols numbers, row-major) without
// copying them: the vector (a std::vector or a point set's Coordinates) is moved into a capsule that
// the array keeps alive.
template <class Allocator>
py::array_t<double> array_owning(std::vector<double, Allocator>&& values, std::vector<py::ssize_t> shape) {
  using Owned = std::vector<double, Allocator>;
  auto* owned = new Owned(std::move(values));
  py::capsule free_when_done(owned, [](void* p) { delete static_cast<Owned*>(p); });
  return py::array_t<double>(std::move(shape), owned->data(), free_when_done);
}
template <class Allocator>
py::array_t<double> array_owning(std::vector<double, Allocator>&& values, std::size_t rows, std::size_t cols) {
  return array_owning(std::move(values), {static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(cols)});
}

// A 1-D float64 array that takes over `values`.
template <class Allocator>
py::array_t<double> array_owning(std::vector<double, Allocator>&& values) {
  const auto size = static_cast<py::ssize_t>(values.size());
  return array_owning(std::move(values), std::vector<py::ssize_t>{size});
}

}  // namespace dfvn::python
