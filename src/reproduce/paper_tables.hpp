// The paper's Table 1 and Table 2 (data/paper_table1.csv, data/paper_table2.csv, compiled in).
#pragma once

#include <optional>
#include <vector>

#include "dfvn/core/point_set.hpp"
#include "dfvn/sampling/method.hpp"

namespace dfvn {

struct PaperTable1Cell {
  int dimension;
  Method method;
  double nn_median;
  double nn_min;
  double seconds;
};

struct PaperTable2Row {
  int steps;
  int reprojection_steps;
  double euler_fps, euler_rmse, rk4_fps, rk4_rmse;
};

const std::vector<PaperTable1Cell>& paper_table1();
const std::vector<PaperTable2Row>& paper_table2();
std::optional<PaperTable1Cell> paper_table1_cell(int dimension, Method method);

}  // namespace dfvn
