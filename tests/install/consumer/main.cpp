// Uses the installed libdfvn: the field c(x) at the point given on the command line, in 3D, seed 7,
// frequency 0.5, printed as `dfvn-sample field` prints its c columns (17 significant digits).
// Usage: consumer X0 X1 X2
// The project has folders core/, io/, stats/, sampling/ and field/ of its own, on its include path
// before the library's, with headers named like libdfvn's: the library's headers must never pick them.
#include <cstdio>
#include <cstdlib>
#include <string>

#include <dfvn/dfvn.hpp>

// The consumer's own headers, after the library's (they refuse to be included before this macro).
#define CONSUMER_OWN_HEADERS
#include "core/point_set.hpp"
#include "core/progress.hpp"
#include "field/dfvn_field.hpp"
#include "io/csv.hpp"
#include "sampling/lattice.hpp"
#include "stats/nearest_neighbour.hpp"

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
  // The consumer's own headers are its own: each names itself.
  if (std::string(consumer_core_progress) != "core/progress" || std::string(consumer_io_csv) != "io/csv") return 3;
  return 0;
}
