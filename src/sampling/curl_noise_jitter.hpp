// Curl noise jittering (CNJ, Section 5.1): every lattice point is traced along the DFVN field for a
// short time (Algorithm 1). The field has no sources or sinks, so points move without clustering.
// On the torus [0,1)^N (the default): the field is periodic and the traces wrap, so there is no
// boundary at all and every lattice point is kept. In a bounded domain (Section 5.4): conformant CNJ
// traces along the field bounded by the domain (Eq. 13 or Bridson's ramp, field/constraint.hpp), so no
// point leaves and every run returns every lattice point; drop mode traces along the free field and
// drops the points that leave (Bærentzen et al. 2023, the paper's Section 5.1 protocol).
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "dfvn/core/domain.hpp"
#include "dfvn/core/progress.hpp"
#include "dfvn/field/constraint.hpp"
#include "dfvn/field/dfvn_field.hpp"
#include "dfvn/integrate/trace.hpp"
#include "dfvn/sampling/lattice.hpp"
#include "dfvn/core/point_set.hpp"

namespace dfvn {

// CNJ's domain (core/domain.hpp's DomainKind, the unit domain of its kind): torus [0,1)^N with opposite
// faces identified; the start set is the cell-centred K^N lattice (the only one that tiles it) whatever
// the protocol. cube: [0,1]^N. ball: its inscribed ball (centre 1/2, radius 1/2); the start set is the
// lattice clipped to it. The sphere has its own CNJ (sampling/sphere_jitter.hpp). data/boundary_shares.md:
// why the torus is the default.
// conformant: the field bounded by the domain (`bound`); drop: the free field, points that leave are
// dropped. The torus has no boundary: it takes conformant (its traces wrap), and drop is refused.
enum class DomainMode { conformant, drop };
DomainMode parse_domain_mode(std::string_view name);  // "conformant" | "drop"
std::string_view to_string(DomainMode mode);

struct CnjOptions {
  // RK4 with Gauss-Newton reprojection after each step. trace.steps = kStepsByDomainMode (the default)
  // takes the domain's step count, cnj_steps(): kFreeFieldSteps for the free field (drop mode, the
  // torus), 1 for the bounded field (conformant cube and ball).
  static constexpr int kStepsByDomainMode = 0;
  TraceOptions trace{.steps = kStepsByDomainMode};
  // At most this many steps: conformant refinements double them kMaxRefinements times, which must stay
  // an int.
  static constexpr int kMaxSteps = 1 << 20;
  // Trace time t = step_scale * dbar(N) * spacing (Section 5.1: proportional to the average
  // neighbour distance). |c| has RMS 1, so t is also the RMS length of a one-step move.
  // Noise frequency in cycles per lattice spacing (the command line's --cycles-per-spacing; not
  // FieldOptions::frequency, which is per unit length): the field's frequency is frequency / spacing.
  // Defaults: the choice of choose_cnj_defaults (reproduce/cnj_study.hpp) on `reproduce cnj-study
  // --realizations 5`, recorded in data/cnj_defaults.md.
  NoiseBasis noise = kDefaultNoiseBasis;
  double step_scale = 0.5;
  double frequency = 0.2;
  // The field's phase in radians (FieldOptions::phase: rotating gradients); 0, the default, is the field
  // without a phase.
  double phase = 0.0;
  // Where the field reads its noise (FieldOptions::transform: --stretch, --time; field/field_transform.hpp).
  NoiseTransform transform{};
  // Bridson's toolbox on the field (FieldOptions::flow: --octaves, --amplitude, --viscous, --body, --vortex;
  // field/bridson_flow.hpp); the default is the field without it.
  FlowOptions flow{};
  // A move of 2^20 lattice spacings is far past any useful jitter (a point moved more than K
  // spacings has left the unit cube unless its streamline loops); the bound keeps every
  // displacement, and the sum of their squares, far from overflow.
  static constexpr double kMaxStepScale = 0x1p20;
  DomainKind domain = kDefaultDomainKind;
  DomainMode domain_mode = DomainMode::conformant;
  Bound bound = Bound::eq13;  // conformant cube and ball: how f_1 meets the boundary (field/constraint.hpp)
  // Eq. (13)'s transition width w in lattice spacings (--boundary-spacings): alpha goes from 0 on the boundary to 1 at w,
  // capped at 1/4 (field/constraint.hpp). Half a spacing, so that the unit protocol's outermost layer
  // starts where alpha reaches 1: wider over-fills the boundary layer, narrower retraces more traces
  // (data/boundary_width.md holds the measurements).
  double boundary_width = 0.5;
  // The field traced along: dfvn (the paper's) or curl (Bridson's curl noise, field/dfvn_field.hpp),
  // which has no reprojection (trace.reprojection must be none) and no boundary treatment (the torus
  // or drop mode only), in 2D and 3D.
  FieldKind field = kDefaultFieldKind;

  void validate() const;  // throws std::invalid_argument naming the option
};

// The integration steps M when CnjOptions::trace.steps is kStepsByDomainMode:
//  the free field (drop mode, and the torus, which has no boundary either): 2, the CNJ study's choice;
//    one RK4 step over the default trace time does not follow the flow from 5D on
//    (data/cnj_defaults.md, data/cnj_paper_lattice.md).
//  the bounded field (conformant cube and ball): 1; the closest pairs form at the walls, where more
//    steps pack worse and cost more (data/cnj_steps_main_job.md).
inline constexpr int kFreeFieldSteps = 2;
int cnj_steps(const CnjOptions& options);
// options.trace with its steps resolved (cnj_steps).
TraceOptions cnj_trace_options(const CnjOptions& options);

// The transition width w in length units for a lattice: min(boundary_width * spacing, 1/4).
double cnj_transition_width(const CnjOptions& options, const LatticeSpec& lattice);

// The field CNJ traces along for a lattice of this spacing: the noise at frequency / spacing cycles per
// unit length, bounded by the cube or ball in conformant mode (transition width min(boundary_width *
// spacing, 1/4)), free in drop mode and periodic on the torus, with the options' field kind, phase and
// transform. animate builds its frames' fields from it too.
FieldOptions cnj_field_options(const CnjOptions& options, double spacing);

// The lattice CNJ starts from: `lattice`, or its cell-centred form on the torus.
LatticeSpec cnj_lattice(const LatticeSpec& lattice, DomainKind domain);

// The start sites: the K^N lattice (cube, torus) or its points strictly inside the inscribed ball
// (ball), in lattice order; sites x N, row-major.
std::vector<double> cnj_start_sites(const LatticeSpec& lattice, DomainKind domain);
std::uint64_t cnj_start_count(const LatticeSpec& lattice, DomainKind domain);

struct CnjResult {
  PointSet points;                  // in the domain: [0,1)^N (torus), [0,1]^N or its inscribed ball
  std::uint64_t started = 0;        // sites traced
  std::uint64_t dropped = 0;        // drop mode: points that left the domain
  std::uint64_t retraced = 0;       // conformant: traces that ended outside and were traced again with more steps
  std::uint64_t kept_at_site = 0;   // conformant: retraced points that no refinement kept inside (stay at their site)
  double trace_time = 0.0;          // t
  double field_frequency = 0.0;     // frequency / spacing (on the torus: the one its wave vectors realise)
  double rms_displacement = 0.0;    // over all traced points, dropped ones included
  // x - x0 of every traced point (dropped ones included; on the torus before wrapping), started x N
  // row-major in site order.
  std::vector<double> displacements;
  TraceStats trace_stats;
};

template <int N>
CnjResult curl_noise_jitter(const LatticeSpec& lattice, const CnjOptions& options, std::uint64_t seed, int threads,
                            const FractionProgress& progress = {});

// Runtime-dimension entry point (the lattice's dimension).
CnjResult curl_noise_jitter(const LatticeSpec& lattice, const CnjOptions& options, std::uint64_t seed, int threads,
                            const FractionProgress& progress = {});

// The rows first .. first + count - 1 of that run (lattice indices, torus or cube; not the ball's clipped
// lattice): every trace depends only on its site, the options and the seed, so the points, displacements
// and counts are the whole run's for those sites (a streamed run's slab, experiment/streamed_sampling.hpp).
CnjResult curl_noise_jitter_range(const LatticeSpec& lattice, const CnjOptions& options, std::uint64_t seed,
                                  std::uint64_t first, std::uint64_t count, int threads);

}  // namespace dfvn
