// Google Benchmark harness for the engine and the statistics (issue: performance).
// Run: build/bench/bench_engine [--benchmark_filter=...] ; medians with --benchmark_repetitions=5.
#include <benchmark/benchmark.h>

#include <vector>

#include "dfvn/animate/animation.hpp"
#include "dfvn/core/hash.hpp"
#include "dfvn/field/dfvn_field.hpp"
#include "dfvn/integrate/trace.hpp"
#include "dfvn/noise/simplex_noise.hpp"
#include "dfvn/noise/simplex_separate.hpp"
#include "dfvn/sampling/curl_noise_jitter.hpp"
#include "dfvn/sampling/jitter.hpp"
#include "dfvn/sampling/lattice.hpp"
#include "dfvn/sampling/poisson_disk.hpp"
#include "dfvn/sampling/sobol.hpp"
#include "dfvn/stats/nearest_neighbour.hpp"

namespace dfvn {
namespace {

template <int N>
std::vector<Vec<N>> bench_points(std::size_t count) {
  std::vector<Vec<N>> points(count);
  for (std::size_t i = 0; i < count; ++i)
    for (int j = 0; j < N; ++j) points[i][j] = 100.0 * random_unit(7, Stream::test, i, static_cast<std::uint64_t>(j));
  return points;
}

// Values and gradients of all N-1 functions in one simplex traversal.
template <int N>
void BM_NoiseFused(benchmark::State& state) {
  const SimplexNoise<N> noise(1);
  const auto points = bench_points<N>(4096);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(noise.evaluate_all(points[i++ & 4095]));
  state.SetItemsProcessed(state.iterations());
}

// The same N-1 functions, one traversal each.
template <int N>
void BM_NoiseSeparate(benchmark::State& state) {
  const SimplexNoise<N> noise(1);
  const auto points = bench_points<N>(4096);
  std::size_t i = 0;
  for (auto _ : state) {
    const Vec<N>& x = points[i++ & 4095];
    for (int m = 0; m < N - 1; ++m) benchmark::DoNotOptimize(noise.template evaluate<1>(x, m));
  }
  state.SetItemsProcessed(state.iterations());
}

// One field evaluation (noise, scaling, cross product), per basis: state.range(0) indexes kAllNoiseBases.
template <int N>
void BM_Field(benchmark::State& state) {
  const NoiseBasis basis = kAllNoiseBases[state.range(0)];
  state.SetLabel(std::string(to_string(basis)));
  const DfvnField<N> field(1, FieldOptions{basis, 1.0});
  const auto points = bench_points<N>(4096);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(field.evaluate(points[i++ & 4095]));
  state.SetItemsProcessed(state.iterations());
}

// One evaluation of Bridson's curl noise (--field curl, 2D and 3D), per basis, beside BM_Field.
template <int N>
void BM_CurlField(benchmark::State& state) {
  const NoiseBasis basis = kAllNoiseBases[state.range(0)];
  state.SetLabel(std::string(to_string(basis)));
  FieldOptions options{basis, 1.0};
  options.kind = FieldKind::curl;
  const DfvnField<N> field(1, options);
  const auto points = bench_points<N>(4096);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(field.evaluate(points[i++ & 4095]));
  state.SetItemsProcessed(state.iterations());
}

// One CNJ point of the main job: one RK4 step with Gauss-Newton reprojection (TraceOptions's default,
// and conformant CNJ's).
template <int N>
void BM_Rk4GaussNewtonStep(benchmark::State& state) {
  const NoiseBasis basis = kAllNoiseBases[state.range(0)];
  state.SetLabel(std::string(to_string(basis)));
  const DfvnField<N> field(1, FieldOptions{basis, 5.0});
  const Tracer<N> tracer(field, TraceOptions{});
  const auto points = bench_points<N>(4096);
  TraceStats stats;
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(tracer.trace(points[i++ & 4095], 0.1, &stats));
  state.SetItemsProcessed(state.iterations());
  state.counters["evals_per_point"] = static_cast<double>(stats.field_evaluations) / static_cast<double>(state.iterations());
}

// Bitangent noise (seeds/004): the reference form, two traversals (S(p) and S(p + offset)), against the
// optimised one, two gradient sets in one traversal (the simplex basis); the document measured 1.95x
// (3D) and 1.81x (4D) on a GTX 1060.
void BM_Bitangent3DSeparate(benchmark::State& state) {
  const SimplexNoise<3> noise(1);
  const auto points = bench_points<3>(4096);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(bitangent_noise_3d(noise, points[i++ & 4095]));
  state.SetItemsProcessed(state.iterations());
}
void BM_Bitangent3DFused(benchmark::State& state) {
  const SimplexNoise<3> noise(1);
  const auto points = bench_points<3>(4096);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(bitangent_noise_3d_fused(noise, points[i++ & 4095]));
  state.SetItemsProcessed(state.iterations());
}
void BM_Bitangent4DSeparate(benchmark::State& state) {
  const SimplexNoise<4> noise(1);
  const auto points = bench_points<4>(4096);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(bitangent_noise_4d(noise, points[i++ & 4095]));
  state.SetItemsProcessed(state.iterations());
}
void BM_Bitangent4DFused(benchmark::State& state) {
  const SimplexNoise<4> noise(1);
  const auto points = bench_points<4>(4096);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(bitangent_noise_4d_fused(noise, points[i++ & 4095]));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Bitangent3DSeparate);
BENCHMARK(BM_Bitangent3DFused);
BENCHMARK(BM_Bitangent4DSeparate);
BENCHMARK(BM_Bitangent4DFused);

// Every dimension; `...` is appended to each registration (e.g. ->DenseRange over the bases).
#define DFVN_BENCH_ALL_DIMENSIONS(name, ...) \
  BENCHMARK_TEMPLATE(name, 2) __VA_ARGS__;    \
  BENCHMARK_TEMPLATE(name, 3) __VA_ARGS__;    \
  BENCHMARK_TEMPLATE(name, 4) __VA_ARGS__;    \
  BENCHMARK_TEMPLATE(name, 5) __VA_ARGS__;    \
  BENCHMARK_TEMPLATE(name, 6) __VA_ARGS__;    \
  BENCHMARK_TEMPLATE(name, 7) __VA_ARGS__;    \
  BENCHMARK_TEMPLATE(name, 8) __VA_ARGS__

constexpr int kLastBasis = static_cast<int>(std::size(kAllNoiseBases)) - 1;
DFVN_BENCH_ALL_DIMENSIONS(BM_NoiseFused);
DFVN_BENCH_ALL_DIMENSIONS(BM_NoiseSeparate);
DFVN_BENCH_ALL_DIMENSIONS(BM_Field, ->DenseRange(0, kLastBasis));
BENCHMARK_TEMPLATE(BM_CurlField, 2)->DenseRange(0, kLastBasis);
BENCHMARK_TEMPLATE(BM_CurlField, 3)->DenseRange(0, kLastBasis);
DFVN_BENCH_ALL_DIMENSIONS(BM_Rk4GaussNewtonStep, ->DenseRange(0, kLastBasis));

// CNJ on the 6^7 paper lattice (279,936 points), all threads, default basis: the 2 s target.
// The paper's protocol: the free field, points that leave [0,1]^N dropped (kFreeFieldSteps RK4 steps).
void BM_CnjPaper7D(benchmark::State& state) {
  const LatticeSpec lattice{7, 6, Protocol::paper};
  CnjOptions options;
  options.domain = DomainKind::cube;
  options.domain_mode = DomainMode::drop;
  for (auto _ : state) benchmark::DoNotOptimize(curl_noise_jitter(lattice, options, 1, 0));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(lattice.point_count()));
}
BENCHMARK(BM_CnjPaper7D)->Unit(benchmark::kMillisecond)->UseRealTime();

// The main job's default: the torus, a periodic field, kFreeFieldSteps RK4 steps, every point kept (the
// 2 s target of the CNJ stage).
void BM_CnjTorus7D(benchmark::State& state) {
  const LatticeSpec lattice{7, 6, Protocol::paper};
  for (auto _ : state) benchmark::DoNotOptimize(curl_noise_jitter(lattice, CnjOptions{}, 1, 0));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(lattice.point_count()));
}
BENCHMARK(BM_CnjTorus7D)->Unit(benchmark::kMillisecond)->UseRealTime();

// The field bounded by [0,1]^N (Eq. 13), one step, every point kept.
void BM_CnjConformant7D(benchmark::State& state) {
  const LatticeSpec lattice{7, 6, Protocol::paper};
  CnjOptions options;
  options.domain = DomainKind::cube;
  for (auto _ : state) benchmark::DoNotOptimize(curl_noise_jitter(lattice, options, 1, 0));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(lattice.point_count()));
}
BENCHMARK(BM_CnjConformant7D)->Unit(benchmark::kMillisecond)->UseRealTime();

// Issue 25's speed target: one animation frame costs no more than one CNJ run of the same lattice.
// BM_CnjSameLattice: CNJ of the cell-centred K^N lattice in the cube (Arg 0 conformant, 1 drop).
// BM_AnimateFrames: animate the same lattice for F frames (frame 0 is that CNJ run); one frame is
// (time(F = 11) - time(F = 1)) / 10. One thread each (the machine is shared: a single thread's time is the
// steadier measure, and both loops parallelise the same way). bench/animation_frame.md records the runs.
template <int N>
void BM_CnjSameLattice(benchmark::State& state) {
  const int grid = static_cast<int>(state.range(0));
  CnjOptions options;
  options.domain = DomainKind::cube;
  options.domain_mode = state.range(1) == 0 ? DomainMode::conformant : DomainMode::drop;
  const LatticeSpec lattice{N, grid, Protocol::fair};
  for (auto _ : state) benchmark::DoNotOptimize(curl_noise_jitter(lattice, options, 1, 1));
}
template <int N>
void BM_AnimateFrames(benchmark::State& state) {
  AnimationOptions options;
  options.dimension = N;
  options.grid = static_cast<int>(state.range(0));
  options.cnj.domain_mode = state.range(1) == 0 ? DomainMode::conformant : DomainMode::drop;
  options.frames = static_cast<int>(state.range(2));
  for (auto _ : state) benchmark::DoNotOptimize(animate(options, 1, 1));
}
BENCHMARK_TEMPLATE(BM_CnjSameLattice, 2)->Args({64, 0})->Args({64, 1})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_TEMPLATE(BM_AnimateFrames, 2)->Args({64, 0, 1})->Args({64, 0, 11})->Args({64, 1, 1})->Args({64, 1, 11})
    ->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_TEMPLATE(BM_CnjSameLattice, 3)->Args({16, 0})->Args({16, 1})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_TEMPLATE(BM_AnimateFrames, 3)->Args({16, 0, 1})->Args({16, 0, 11})->Args({16, 1, 1})->Args({16, 1, 11})
    ->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_TEMPLATE(BM_CnjSameLattice, 5)->Args({5, 0})->Args({5, 1})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_TEMPLATE(BM_AnimateFrames, 5)->Args({5, 0, 1})->Args({5, 0, 11})->Args({5, 1, 1})->Args({5, 1, 3})
    ->Unit(benchmark::kMillisecond)->UseRealTime();

// Nearest-neighbour distances of 279,936 jittered 7D points (KD-tree build + k = 2 queries).
void BM_NearestNeighbours7D(benchmark::State& state) {
  const PointSet points = jittered_lattice(LatticeSpec{7, 6, Protocol::paper}, 1, 0);
  const auto backend = state.range(0) == 0 ? KnnBackend::nanoflann : KnnBackend::flann;
  state.SetLabel(std::string(to_string(backend)));
  for (auto _ : state) benchmark::DoNotOptimize(nearest_neighbour_distances(points, backend, 0));
}
BENCHMARK(BM_NearestNeighbours7D)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// The main job's Sobol (2^18 points, Owen) and Poisson disk (279,936 points, r = 0.1 on [0, 0.6]^7) sets,
// in no spatial order: nanoflann build + k = 2 queries on one thread (issue 22: queries in tree order).
void BM_NearestNeighboursUnordered7D(benchmark::State& state) {
  PoissonDiskOptions o;
  o.radius = 0.1;
  o.domain = Box{0.0, 0.6};
  o.max_points = 279936;
  const PointSet points = state.range(0) == 0 ? sobol_points(7, 1u << 18, Box{0.0, 0.6}, Scramble::owen, 1, 0)
                                              : poisson_disk(7, o, 1, 0).points;
  state.SetLabel(state.range(0) == 0 ? "sobol" : "pds");
  for (auto _ : state) benchmark::DoNotOptimize(nearest_neighbour_distances(points, KnnBackend::nanoflann, 1));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(points.size()));
}
BENCHMARK(BM_NearestNeighboursUnordered7D)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// Poisson disk on [0,1]^5 with r = 0.1, saturated (about 71,600 points); arg: threads (0 = all).
void BM_PoissonDisk5D(benchmark::State& state) {
  PoissonDiskOptions o;
  o.radius = 0.1;
  std::size_t points = 0;
  for (auto _ : state) points = poisson_disk(5, o, 1, static_cast<int>(state.range(0))).points.size();
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(points));
}
BENCHMARK(BM_PoissonDisk5D)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();

// The main job's Poisson disk row: r = 0.1 on [0, 0.6]^7, 6^7 = 279,936 points asked for (reached
// before the set saturates); arg: threads (0 = all).
void BM_PoissonDiskPaper7D(benchmark::State& state) {
  PoissonDiskOptions o;
  o.radius = 0.1;
  o.domain = Box{0.0, 0.6};
  o.max_points = 279936;
  for (auto _ : state) benchmark::DoNotOptimize(poisson_disk(7, o, 1, static_cast<int>(state.range(0))));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(o.max_points));
}
BENCHMARK(BM_PoissonDiskPaper7D)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();

// Owen-scrambled Sobol at the sizes scripts/bench_vs_anchors compares with SciPy: 2^17 points in 6D and
// 2^18 in 7D (args: dimension, log2 count), all threads.
void BM_Sobol(benchmark::State& state) {
  const auto dimension = static_cast<int>(state.range(0));
  const std::uint64_t count = std::uint64_t{1} << state.range(1);
  for (auto _ : state)
    benchmark::DoNotOptimize(sobol_points(dimension, count, Box{}, Scramble::owen, 1, 0));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(count));
}
BENCHMARK(BM_Sobol)->Args({6, 17})->Args({7, 18})->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace dfvn

BENCHMARK_MAIN();
