// Distance-step throughput at the paper's scale: about 1.8 M query points near a closed
// nominal of about 17 k triangles (a finely tessellated torus), over the grid and by brute
// force, on one and two threads; plus the grid build and the fast winding number.
// Counters: queries/s (items_per_second) and triangles tested per query.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <numbers>
#include <random>
#include <string>

#include <tbb/global_control.h>

#include "distance/signed_distance.hpp"
#include "mesh/mesh_reader.hpp"
#include "reference/winding_number.hpp"
#include "search/grid_builder.hpp"
#include "search/indexed_reference.hpp"
#include "search/search_index.hpp"
#include "workload.hpp"

namespace {

using ncv::Vec3;

// 130 x 66 quads = 17,160 triangles, minor radius 10 around a major radius 40 (mm).
ncv::Mesh torus() {
  constexpr int nu = 130, nv = 66;
  ncv::Mesh mesh;
  for (int i = 0; i < nu; ++i) {
    const double u = 2 * std::numbers::pi * i / nu;
    for (int j = 0; j < nv; ++j) {
      const double v = 2 * std::numbers::pi * j / nv;
      const double ring = 40 + 10 * std::cos(v);
      mesh.vertices.push_back({ring * std::cos(u), ring * std::sin(u), 10 * std::sin(v)});
    }
  }
  const auto at = [](int i, int j) { return static_cast<std::uint32_t>((i % nu) * nv + j % nv); };
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return mesh;
}

struct Scene {
  ncv::IndexedReference reference = ncv::index_reference(torus(), "torus");
  const ncv::ReferenceSurface& nominal = *reference.surface;
  ncv::SearchIndex search{reference};
  std::vector<Vec3> points;
  std::vector<Vec3> shuffled;

  // Samples of a machined surface: on the nominal's smooth surface, off by up to 0.2 mm,
  // in sweeps of 1,000 along v (as a sampled workpiece delivers them, triangle after
  // triangle, neighbours after neighbours); `shuffled` holds them in random order.
  Scene() {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    constexpr std::size_t rows = 1800, columns = 1000;
    points.reserve(rows * columns);
    for (std::size_t row = 0; row < rows; ++row) {
      for (std::size_t column = 0; column < columns; ++column) {
        const double u = 2 * std::numbers::pi * (static_cast<double>(row) + unit(rng)) / rows;
        const double v = 2 * std::numbers::pi * (static_cast<double>(column) + unit(rng)) / columns;
        const double r = 10 + 0.4 * (unit(rng) - 0.5);
        const double ring = 40 + r * std::cos(v);
        points.push_back({ring * std::cos(u), ring * std::sin(u), r * std::sin(v)});
      }
    }
    shuffled = points;
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
  }
};

const Scene& scene() {
  static const Scene instance;
  return instance;
}

void run_distances(benchmark::State& state, bool use_grid, const std::vector<Vec3>& all,
                   std::size_t count, ncv::SignMethod method) {
  const Scene& s = scene();
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                              static_cast<std::size_t>(state.range(0)));
  const std::span<const Vec3> points(all.data(), count);
  ncv::SearchStatistics stats;
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        use_grid ? ncv::compute_signed_distances(s.search, points, {}, method, &stats)
                 : ncv::compute_signed_distances(s.nominal, points, {}, method, &stats));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * count));
  state.counters["triangles/query"] = stats.triangles_per_query();
  state.counters["considered/query"] =
      static_cast<double>(stats.triangles_considered) / static_cast<double>(stats.queries);
  state.counters["cells/query"] =
      static_cast<double>(stats.cells_visited) / static_cast<double>(stats.queries);
}

void BM_GridPseudonormal(benchmark::State& state) {
  run_distances(state, true, scene().points, scene().points.size(), ncv::SignMethod::pseudonormal);
}
void BM_GridPseudonormalShuffled(benchmark::State& state) {
  run_distances(state, true, scene().shuffled, scene().shuffled.size(),
                ncv::SignMethod::pseudonormal);
}
void BM_GridWinding(benchmark::State& state) {
  run_distances(state, true, scene().points, scene().points.size(), ncv::SignMethod::winding);
}
void BM_BruteForce(benchmark::State& state) {
  run_distances(state, false, scene().points, 2000, ncv::SignMethod::pseudonormal);
}

void BM_GridBuild(benchmark::State& state) {
  const Scene& s = scene();
  ncv::GridStatistics stats;
  for (auto _ : state) benchmark::DoNotOptimize(ncv::build_background_grid(s.nominal, {}, &stats));
  state.counters["cells"] = static_cast<double>(stats.cells);
  state.counters["references/triangle"] = stats.references_per_triangle;
}

void BM_WindingTreeBuild(benchmark::State& state) {
  const Scene& s = scene();
  for (auto _ : state) benchmark::DoNotOptimize(ncv::WindingNumberTree(s.nominal.corners()));
}

// The real finishing workload when NCV_BENCH_WORKPIECE and NCV_BENCH_NOMINAL name STL files
// (scripts/bench.sh sets them): the workpiece sampled at 0.1 % against the nominal's grid.
const ncv::bench::Workload* workload() {
  static const std::unique_ptr<ncv::bench::Workload> instance =
      []() -> std::unique_ptr<ncv::bench::Workload> {
    const char* workpiece = std::getenv("NCV_BENCH_WORKPIECE");
    const char* nominal = std::getenv("NCV_BENCH_NOMINAL");
    if (!workpiece || !nominal) return nullptr;
    return std::make_unique<ncv::bench::Workload>(ncv::bench::load_workload(workpiece, nominal));
  }();
  return instance.get();
}

void BM_WorkloadGrid(benchmark::State& state) {
  const ncv::bench::Workload* w = workload();
  if (!w) {
    state.SkipWithError("NCV_BENCH_WORKPIECE / NCV_BENCH_NOMINAL not set");
    return;
  }
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                              static_cast<std::size_t>(state.range(0)));
  // Built once, as `run` builds it in its grid-build phase.
  static const ncv::SearchIndex search(w->nominal);
  ncv::SearchStatistics stats;
  for (auto _ : state) {
    benchmark::DoNotOptimize(ncv::compute_signed_distances(search, w->points, {},
                                                           ncv::SignMethod::pseudonormal, &stats));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * w->points.size()));
  state.counters["triangles/query"] = stats.triangles_per_query();
  state.counters["considered/query"] =
      static_cast<double>(stats.triangles_considered) / static_cast<double>(stats.queries);
  state.counters["cells/query"] =
      static_cast<double>(stats.cells_visited) / static_cast<double>(stats.queries);
}

// build_background_grid alone (no reading, welding, topology or writing) on the nominal named
// by NCV_BENCH_GRID_NOMINAL_<arg> (scripts/bench.sh: 0 to 3 for 17 k, 170 k, 1 M, 1.7 M).
void BM_WorkloadGridBuild(benchmark::State& state) {
  const std::string name = "NCV_BENCH_GRID_NOMINAL_" + std::to_string(state.range(0));
  const char* path = std::getenv(name.c_str());
  if (!path) {
    state.SkipWithError((name + " not set").c_str());
    return;
  }
  const ncv::ReferenceSurface nominal(ncv::read_mesh(path), path);
  ncv::GridStatistics stats;
  for (auto _ : state) benchmark::DoNotOptimize(ncv::build_background_grid(nominal, {}, &stats));
  state.counters["triangles"] = static_cast<double>(nominal.triangle_count());
  state.counters["bytes/triangle"] =
      static_cast<double>(stats.bytes) / static_cast<double>(nominal.triangle_count());
}

}  // namespace

BENCHMARK(BM_WorkloadGridBuild)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Arg(3)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_WorkloadGrid)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_GridPseudonormal)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_GridPseudonormalShuffled)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_GridWinding)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_BruteForce)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_GridBuild)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_WindingTreeBuild)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_MAIN();
