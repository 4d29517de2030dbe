// Uses the installed libdfvn: the field c(x) at the point given on the command line, in 3D, seed 7,
// frequency 0.5, printed as `dfvn-sample field` prints its c columns (17 significant digits).
// Usage: consumer X0 X1 X2
#include <cstdio>
#include <cstdlib>
#include <string>

#include <dfvn/field/dfvn_field.hpp>
#include <dfvn/io/csv.hpp>

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: consumer X0 X1 X2\n");
    return 2;
  }
  dfvn::Vec<3> x;
  for (int j = 0; j < 3; ++j) x[j] = std::strtod(argv[j + 1], nullptr);
  const dfvn::DfvnField<3> field(7, dfvn::FieldOptions{dfvn::NoiseBasis::turning_bands, 0.5});
  const dfvn::Vec<3> c = field.velocity(x);
  std::string line;
  for (int j = 0; j < 3; ++j) {
    if (j) line += ',';
    dfvn::append_double(line, c[j]);
  }
  std::printf("%s\n", line.c_str());
  return 0;
}
