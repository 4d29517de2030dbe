#include "numpy_points.hpp"

#include <string>

namespace dfvn::python {

PointRows point_rows(const PointArray& points, int min_dimension, int max_dimension, std::size_t min_rows) {
  const std::string allowed = min_dimension == max_dimension
                                  ? std::to_string(min_dimension)
                                  : std::to_string(min_dimension) + ".." + std::to_string(max_dimension);
  const bool one_dimensional = points.ndim() == 1 && min_dimension == 1;
  if (points.ndim() != 2 && !one_dimensional)
    throw py::value_error("points must be a 2-D array of shape (points, N) with N in " + allowed + ", got " +
                          std::to_string(points.ndim()) + " dimension(s); one point x is x.reshape(1, -1)");
  const auto dimension = one_dimensional ? py::ssize_t{1} : points.shape(1);
  if (dimension < min_dimension || dimension > max_dimension)
    throw py::value_error("points must have N = " + allowed + " columns, got " + std::to_string(dimension));
  const auto rows = static_cast<std::size_t>(points.shape(0));
  if (rows < min_rows)
    throw py::value_error("points must hold at least " + std::to_string(min_rows) + " points, got " + std::to_string(rows));
  return {points.data(), rows, static_cast<int>(dimension)};
}

py::array_t<double> new_array(std::size_t rows, std::size_t cols) {
  return py::array_t<double>({static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(cols)});
}

}  // namespace dfvn::python
