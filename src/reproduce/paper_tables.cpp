#include "dfvn/reproduce/paper_tables.hpp"

#include <sstream>
#include <stdexcept>
#include <string>

#include "paper_tables_data.hpp"

namespace dfvn {

namespace {
std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) out.push_back(cell);
  return out;
}
}  // namespace

const std::vector<PaperTable1Cell>& paper_table1() {
  static const std::vector<PaperTable1Cell> table = [] {
    std::vector<PaperTable1Cell> rows;
    std::istringstream in(kPaperTable1Csv);
    std::string line;
    std::getline(in, line);  // dim,method,nn_median,nn_min,seconds
    while (std::getline(in, line)) {
      if (line.empty()) continue;
      const auto f = split(line);
      if (f.size() != 5) throw std::logic_error("malformed paper_table1.csv row: " + line);
      rows.push_back({std::stoi(f[0]), parse_method(f[1]), std::stod(f[2]), std::stod(f[3]), std::stod(f[4])});
    }
    return rows;
  }();
  return table;
}

const std::vector<PaperTable2Row>& paper_table2() {
  static const std::vector<PaperTable2Row> table = [] {
    std::vector<PaperTable2Row> rows;
    std::istringstream in(kPaperTable2Csv);
    std::string line;
    std::getline(in, line);  // steps,reprojection_steps,euler_fps,euler_rmse,rk4_fps,rk4_rmse
    while (std::getline(in, line)) {
      if (line.empty()) continue;
      const auto f = split(line);
      if (f.size() != 6) throw std::logic_error("malformed paper_table2.csv row: " + line);
      rows.push_back({std::stoi(f[0]), std::stoi(f[1]), std::stod(f[2]), std::stod(f[3]), std::stod(f[4]), std::stod(f[5])});
    }
    return rows;
  }();
  return table;
}

std::optional<PaperTable1Cell> paper_table1_cell(int dimension, Method method) {
  for (const auto& c : paper_table1())
    if (c.dimension == dimension && c.method == method) return c;
  return std::nullopt;
}

}  // namespace dfvn
