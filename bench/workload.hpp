// The paper-scale workload the benchmark programs measure: a workpiece sampled (scheme I) at
// a fraction of its diagonal (0.1 %, the paper's δ, by default) against a nominal's grid;
// and the helpers the search tools share.
#pragma once

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <utility>
#include <vector>

#include "distance/signed_distance.hpp"
#include "mesh/mesh_reader.hpp"
#include "sampling/sampling.hpp"
#include "search/closest_point_search.hpp"
#include "search/indexed_reference.hpp"

namespace ncv::bench {

struct Workload {
  IndexedReference nominal;
  std::vector<Vec3> points;  // the samples, global frame (load_workload) or local
};

inline Workload load_workload(const char* workpiece_path, const char* nominal_path,
                              double step_fraction = 0.001) {
  Workload w;
  w.nominal = index_reference(read_mesh(nominal_path), nominal_path);
  Mesh workpiece = read_mesh(workpiece_path);
  const double step = step_fraction * bounding_box(workpiece).diagonal();
  const Buffer<Vec3> points =
      sample_mesh(std::move(workpiece), step, SamplingScheme::all).positions;
  w.points.assign(points.begin(), points.end());
  return w;
}

// The command-line tools' workload: WORKPIECE NOMINAL [STEP_FRACTION] from the arguments,
// with the samples moved into the nominal's local frame, where its grid and the search live.
// Missing arguments or an unreadable mesh: one line on standard error and exit status 2.
inline Workload load_local_workload(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s WORKPIECE NOMINAL [STEP_FRACTION]\n", argv[0]);
    std::exit(2);
  }
  try {
    Workload w = load_workload(argv[1], argv[2], argc > 3 ? std::atof(argv[3]) : 0.001);
    for (Vec3& p : w.points) p = w.nominal.surface->to_local(p);
    return w;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", argv[0], e.what());
    std::exit(2);
  }
}

// Searches every point in turn as the distance step does, the hint dropped at the start of
// each block; on_hit(i, hit) receives each result.
template <class OnHit>
void search_in_step_order(GridSearcher& search, const std::vector<Vec3>& points, OnHit&& on_hit) {
  SearchCounters counters;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i % kDistanceBlockSize == 0) search.forget_hint();
    on_hit(i, search.closest(points[i], counters));
  }
}

inline double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

}  // namespace ncv::bench
