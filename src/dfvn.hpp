// <dfvn/dfvn.hpp>: the whole public API of libdfvn in one include. Every header below is installed
// under <prefix>/include/dfvn/ and may also be included on its own; nothing else is installed (the
// headers of private dependencies, template internals, the reproductions, the plots and the text
// helpers of the command line stay inside the library). cmake/install.cmake lists the same headers, and
// the install test checks that the two lists agree.
#pragma once

#include "dfvn/animate/animation.hpp"

#include "dfvn/core/bulk_memory.hpp"
#include "dfvn/core/dimension.hpp"
#include "dfvn/core/domain.hpp"
#include "dfvn/core/image.hpp"
#include "dfvn/core/point_set.hpp"
#include "dfvn/core/progress.hpp"
#include "dfvn/core/quantile.hpp"
#include "dfvn/core/seeds.hpp"
#include "dfvn/core/simd.hpp"
#include "dfvn/core/stopwatch.hpp"
#include "dfvn/core/torus.hpp"
#include "dfvn/core/tree_sum.hpp"

#include "dfvn/experiment/experiment.hpp"
#include "dfvn/experiment/realizations.hpp"
#include "dfvn/experiment/streamed_sampling.hpp"

#include "dfvn/field/constraint.hpp"
#include "dfvn/field/cross_product.hpp"
#include "dfvn/field/dfvn_field.hpp"
#include "dfvn/field/obstacles.hpp"
#include "dfvn/field/bridson_flow.hpp"
#include "dfvn/field/diagnose.hpp"
#include "dfvn/field/evaluate_points.hpp"
#include "dfvn/field/field_transform.hpp"

#include "dfvn/integrate/trace.hpp"
#include "dfvn/integrate/trace_points.hpp"

#include "dfvn/io/atomic_file.hpp"
#include "dfvn/io/csv.hpp"
#include "dfvn/io/field_csv.hpp"
#include "dfvn/io/png.hpp"
#include "dfvn/io/point_file.hpp"
#include "dfvn/io/point_reader.hpp"
#include "dfvn/io/point_sidecar.hpp"
#include "dfvn/io/utk_bin.hpp"

#include "dfvn/noise/gradient_noise.hpp"
#include "dfvn/noise/noise_domain.hpp"
#include "dfvn/noise/noise_functions.hpp"
#include "dfvn/noise/noise_transforms.hpp"
#include "dfvn/noise/simplex_noise.hpp"
#include "dfvn/noise/rotating_gradients.hpp"
#include "dfvn/noise/simplex_separate.hpp"
#include "dfvn/noise/steerable_noise.hpp"
#include "dfvn/noise/turning_bands.hpp"

#include "dfvn/quadrature/genz.hpp"

#include "dfvn/sampling/curl_noise_jitter.hpp"
#include "dfvn/sampling/halton.hpp"
#include "dfvn/sampling/jitter.hpp"
#include "dfvn/sampling/latin_hypercube.hpp"
#include "dfvn/sampling/lattice.hpp"
#include "dfvn/sampling/method.hpp"
#include "dfvn/sampling/poisson_disk.hpp"
#include "dfvn/sampling/sobol.hpp"
#include "dfvn/sampling/sphere_jitter.hpp"

#include "dfvn/stats/discrepancy.hpp"
#include "dfvn/stats/distance_scale.hpp"
#include "dfvn/stats/geodesic.hpp"
#include "dfvn/stats/lattice_displacement.hpp"
#include "dfvn/stats/nearest_neighbour.hpp"
#include "dfvn/stats/periodic_neighbours.hpp"
#include "dfvn/stats/point_set_statistics.hpp"
#include "dfvn/stats/radial_distribution.hpp"
#include "dfvn/stats/spectrum.hpp"

#include "dfvn/warp/image_warp.hpp"
