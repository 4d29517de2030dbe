// `dfvn-sample reproduce bridson`: Bridson, Hourihan and Nordenstam's Figure 2 (seed 003) with the toolbox of
// field/bridson_flow.hpp, 3D curl noise in the unit cube, and bridson.md's checks from the field itself.
//   wake: a sphere moving down (--body, velocity V, spinning about its axis) with turbulence only behind it
//         (--amplitude obstacles:D times a height ramp above it, --octaves K): particles traced in the body's
//         frame (c - V, where the body stands still and the fluid streams up past it) from a grid below it.
//   ring: a vortex ring (--vortex ring:...) rising at a constant speed through the cube towards a fixed sphere
//         (--obstacle), the turbulence switched on above the sphere (--amplitude height:...): the ring's own
//         particles, traced along the field of each moment (the ring's centre moves, everything else stays).
// Checks, by central differences and on sampled surfaces of the fields the figures use: the divergence, c . n on
// the walls and the fixed sphere, (c - V - W x r) . n on the moving body, c = 0 on viscous walls (the wake's field
// with --viscous: also c = V + W x r on the body), and the energy of each octave against the octave gain.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "dfvn/core/progress.hpp"

namespace dfvn {

struct BridsonConfig {
  double frequency = 2.5;         // cycles per unit length of octave 0
  int octaves = 3;
  double octave_gain = 0.79370052598409973738;  // Kolmogorov's 2^(-1/3) (field/bridson_flow.hpp)
  double boundary_width = 0.06;   // w: the solids' transition width (octave o: w / 2^o)
  int grid = 24;                  // K x K particles per scene
  int steps = 128;                // RK4 steps per trace
  int image = 512;                // each PNG's side in pixels
  int check_points = 4000;        // random points of the divergence check, and points per checked surface
  std::uint64_t seed = 1;
  int threads = 0;
  std::string out_dir = "out/bridson";

  void validate() const;  // throws std::invalid_argument naming the option
};

// One checked quantity: what, on which field, the measured number and the bound it must meet.
struct BridsonCheck {
  std::string what, field;
  double value = 0.0, bound = 0.0;
  bool passed() const { return value <= bound; }
};

struct BridsonOctaveEnergy {
  int octave = 0;
  double measured = 0.0;  // mean |n_{o+1} c_{o+1} - n_o c_o|^2 / n_K^2 (the nested fields' difference)
  double law = 0.0;       // a_o^2 = g^(2o) / sum_k g^(2k)
};

struct BridsonResult {
  BridsonConfig config;
  std::vector<double> wake_traces, ring_traces;  // particle-major: (steps + 1) points of 3 coordinates
  std::vector<BridsonCheck> checks;
  std::vector<BridsonOctaveEnergy> energies;
  double inviscid_slip = 0.0;  // max |c - V - W x r| on the inviscid body's surface (tangential: > 0)
  double seconds = 0.0;
  std::string machine;
  bool passed() const;
};

BridsonResult run_bridson(const BridsonConfig& config, const StageProgress& progress = {});
std::vector<double> bridson_stage_weights(const BridsonConfig& config);
// DIR/bridson.md, DIR/bridson_checks.csv, DIR/bridson_octaves.csv, DIR/wake.png, DIR/ring.png (side views, x right,
// z up), DIR/wake_traces.csv and DIR/ring_traces.csv. Returns the Markdown.
// `log` says how to get the titled wake.png and ring.png without gnuplot (wake_traces.png, ring_traces.png:
// the side views alone, always written).
std::string write_bridson(const BridsonResult& result, const std::function<void(const std::string&)>& log = {});
std::vector<std::string> bridson_output_files();
std::string bridson_markdown(const BridsonResult& result);

}  // namespace dfvn
