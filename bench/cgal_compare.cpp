// The distance search beside CGAL's AABB tree on the same samples, one thread:
//   ncverify_cgal_compare WORKPIECE.stl NOMINAL.stl [STEP_FRACTION]
// samples the workpiece (scheme I, default δ = 0.1 % of its diagonal) and finds every
// sample's closest nominal point three ways: ncverify's grid search (in the distance step's
// order, the hint dropped every block of 512), CGAL's `closest_point_and_primitive` from its
// default start (`accelerate_distance_queries`), and CGAL's with the previous sample's hit
// as the hint. Closest points only: neither side computes a sign here. Prints the time per
// sample of each (median of 3 passes) and how many squared distances differ by more than
// 1e-9 of the coordinate scale (CGAL rounds its own way).
// Built only where CGAL is installed (Debian: libcgal-dev; scripts/setup.sh does not).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include "search/closest_point_search.hpp"
#include "search/search_index.hpp"
#include "util/stopwatch.hpp"
#include "workload.hpp"

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Triangle = Kernel::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle>::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Kernel::Point_3 point(const ncv::Vec3& v) {
  return {v[0], v[1], v[2]};
}

// Median over passes of one pass's seconds per sample; `pass` fills squared distances.
double time_per_sample(const std::function<void(std::vector<double>&)>& pass,
                       std::vector<double>& squared) {
  std::vector<double> times;
  for (int round = 0; round < 3; ++round) {
    const ncv::Stopwatch clock;
    pass(squared);
    times.push_back(clock.seconds());
  }
  return ncv::bench::median(times) / static_cast<double>(squared.size());
}

std::size_t differing(const std::vector<double>& a, const std::vector<double>& b, double scale) {
  std::size_t count = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::fabs(std::sqrt(a[i]) - std::sqrt(b[i])) > 1e-9 * scale) ++count;
  }
  return count;
}

}  // namespace

int main(int argc, char** argv) {
  ncv::bench::Workload w = ncv::bench::load_local_workload(argc, argv);
  const ncv::ReferenceSurface& nominal = *w.nominal.surface;
  const std::vector<ncv::Vec3>& points = w.points;
  const double scale = std::max(ncv::max_abs(w.nominal.grid.bounds().min),
                                ncv::max_abs(w.nominal.grid.bounds().max));

  std::vector<Triangle> triangles;
  triangles.reserve(nominal.triangle_count());
  const ncv::MeshCorners corners = nominal.corners();
  for (std::size_t t = 0; t < corners.size(); ++t) {
    const ncv::TriangleCorners c = corners[t];
    triangles.emplace_back(point(c[0]), point(c[1]), point(c[2]));
  }
  const ncv::Stopwatch build_clock;
  Tree tree(triangles.begin(), triangles.end());
  tree.build();
  tree.accelerate_distance_queries();
  const double build_seconds = build_clock.seconds();

  const ncv::SearchIndex index(w.nominal);
  ncv::GridSearcher search(index);
  std::vector<double> grid_squared(points.size()), default_squared(points.size()),
      hinted_squared(points.size());
  const double grid_time = time_per_sample(
      [&](std::vector<double>& squared) {
        ncv::bench::search_in_step_order(
            search, points,
            [&](std::size_t i, const ncv::ClosestHit& hit) { squared[i] = hit.squared_distance; });
      },
      grid_squared);
  const double default_time = time_per_sample(
      [&](std::vector<double>& squared) {
        for (std::size_t i = 0; i < points.size(); ++i) {
          const Kernel::Point_3 q = point(points[i]);
          squared[i] = CGAL::squared_distance(q, tree.closest_point_and_primitive(q).first);
        }
      },
      default_squared);
  const double hinted_time = time_per_sample(
      [&](std::vector<double>& squared) {
        Tree::Point_and_primitive_id hit = tree.closest_point_and_primitive(point(points[0]));
        for (std::size_t i = 0; i < points.size(); ++i) {
          const Kernel::Point_3 q = point(points[i]);
          hit = tree.closest_point_and_primitive(q, hit);
          squared[i] = CGAL::squared_distance(q, hit.first);
        }
      },
      hinted_squared);

  std::printf("%zu samples, %zu nominal triangles; CGAL tree built in %.3f s\n", points.size(),
              nominal.triangle_count(), build_seconds);
  std::printf("%-40s%12s%12s\n", "closest point, 1 thread", "ns/sample", "differing");
  std::printf("%-40s%12.0f%12s\n", "ncverify grid search", 1e9 * grid_time, "-");
  std::printf("%-40s%12.0f%12zu\n", "CGAL AABB tree", 1e9 * default_time,
              differing(grid_squared, default_squared, scale));
  std::printf("%-40s%12.0f%12zu\n", "CGAL AABB tree, previous hit as hint", 1e9 * hinted_time,
              differing(grid_squared, hinted_squared, scale));
  return 0;
}
