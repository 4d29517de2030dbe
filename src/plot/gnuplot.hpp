// Figures drawn by gnuplot. The gnuplot programs are scripts/*.gp, compiled into the library at
// configure time, so a figure needs neither a shell nor the source tree: gnuplot is started with an
// argument list (posix_spawn, no shell), the program reads its inputs as ARG1, ARG2, ... (paths of any
// spelling, `it's` included), and the PNG is written whole or not at all (io/atomic_file.hpp). gnuplot
// works in a private directory under $TMPDIR that is removed on every exit path; on SIGINT, SIGTERM,
// SIGHUP and SIGPIPE (after remove_temporaries_on_signals()) gnuplot is killed first.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace dfvn {

enum class PlotProgram {
  figure4,      // scripts/figure4.gp: Table 1's radial distribution functions
  figure5,      // scripts/figure5.gp: Table 2's image-warping montage
  integration,  // scripts/integration.gp: integration error against points, one figure per dimension
  cnj_study,    // scripts/cnj_study.gp: CNJ against jitter
  spectrum,     // scripts/spectrum.gp: periodogram and radial average
  animation,    // scripts/animation.gp: animate's strip of frames with trails
  figure8,      // scripts/figure8.gp: drop against conformant animation, count per frame and tracks
  curl_obstacle,  // scripts/curl_obstacle.gp: Bridson's Figure 1, curl noise streamlines around a disc
  figure6,      // scripts/figure6.gp: the sphere warp's montage, a row of increasing t and the error maps
  figure7,      // scripts/figure7.gp: the disc-bounded warp's montage, 2D and the 3D slices, labelled
  slope,        // scripts/slope.gp: figure9 and figure10, traces over the height field with axes and arrows
  titled,       // scripts/titled.gp: a square image over the unit square with axes and a title (bridson)
};

// "figure4.gp", ...; and the program's text as compiled in.
std::string_view plot_program_name(PlotProgram program);
std::string_view plot_program_text(PlotProgram program);

// The first executable `gnuplot` in the directories of PATH, or "" if there is none.
std::string find_gnuplot();

// A figure that was asked for and could not be drawn (gnuplot failed or wrote nothing); the message
// names the figure and carries gnuplot's own last error line.
class PlotError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws PlotError naming TMPDIR when gnuplot is installed but no figure could be drawn for want of
// a temporary folder. Commands that draw figures call it before their work, not after.
void check_figure_prerequisites();

// Draws `output` (a PNG) by running `program` with ARG1 = a temporary PNG path and ARG2.. =
// `arguments` (at most 8: gnuplot 5.4 passes ARG1..ARG9). On success the PNG replaces `output` whole,
// gnuplot's warnings go to `log`, and the result is true. Without gnuplot, `log` says how to get it and
// the result is false. Throws PlotError when gnuplot fails, and std::runtime_error when `output`
// cannot be written.
bool draw_figure(PlotProgram program, const std::string& output, const std::vector<std::string>& arguments,
                 const std::function<void(const std::string&)>& log);

}  // namespace dfvn
