#include "statistics/error_regions.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <algorithm>
#include <array>

#include "geometry/linear_patch.hpp"
#include "sampling/lattice_triangles.hpp"
#include "util/block_offsets.hpp"
#include "util/disjoint_sets.hpp"

namespace ncv {

namespace {

// One triangle's side of a mesh edge, the edge named by its vertices in ascending order.
struct EdgeSide {
  std::uint32_t v0, v1;
  std::uint32_t triangle;
  int corner;  // the edge runs from this corner to the next
};

// A lattice point on an edge at parameter step / steps from the edge's lower vertex.
struct EdgePoint {
  std::uint64_t step, steps;
  std::uint64_t sample;
};

// Per sample: 0 within tolerance, else 1 + RegionKind.
using KindCode = std::uint8_t;
constexpr KindCode kWithin = 0;

KindCode kind_code(double d, const Tolerance& zone) {
  switch (classify(d, zone)) {
    case ToleranceClass::excess:
      return 1 + static_cast<KindCode>(RegionKind::excess);
    case ToleranceClass::gouge:
      return 1 + static_cast<KindCode>(RegionKind::gouge);
    case ToleranceClass::within:
      break;
  }
  return kWithin;
}

constexpr std::size_t kBlock = 1 << 14;

// Works on the out-of-tolerance samples and the triangles holding one only (on a finished
// part a few per cent of either): they are found in parallel, and only they are joined,
// measured and labelled. The union-find runs over the out-of-tolerance samples numbered in
// sample order, so its roots, and the regions' order and areas (summed triangle by triangle
// in mesh order), are those of a pass over every sample.
class RegionBuilder {
 public:
  RegionBuilder(const SampleSet& samples, std::span<const double> d, const Tolerance& zone)
      : samples_(samples), d_(d), zone_(zone), kind_(d.size()), member_(d.size()) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, d.size(), kBlock), [&](const auto& r) {
      for (std::size_t s = r.begin(); s != r.end(); ++s) kind_[s] = kind_code(d[s], zone);
    });
    // Numbered in sample order, block by block in parallel (a serial pass over every sample
    // was a fifth of the regions' time on a finished part). Only out-of-tolerance samples'
    // numbers are ever read.
    members_ =
        kept_indices<std::uint64_t>(d.size(), [&](std::size_t s) { return kind_[s] != kWithin; });
    tbb::parallel_for(std::size_t{0}, members_.size(),
                      [&](std::size_t k) { member_[members_[k]] = static_cast<std::uint32_t>(k); });
    sets_ = DisjointSets(members_.size());
    find_touched_triangles();
  }

  void connect_lattices() {
    for (const std::uint32_t t : touched_) {
      for_each_lattice_triangle(samples_, t,
                                [&](std::uint64_t a, std::uint64_t b, std::uint64_t c) {
                                  connect(a, b);
                                  connect(b, c);
                                  connect(c, a);
                                });
    }
  }

  // Only lattices of size >= 3 put samples inside an edge; the corners are shared already.
  // An edge joins samples only when a touched triangle lies on it, so only the sides of
  // touched triangles and of triangles whose edge has both ends on a touched one are sorted.
  void connect_across_edges() {
    const Mesh& mesh = samples_.mesh;
    std::vector<bool> on_touched(mesh.vertex_count(), false);
    for (const std::uint32_t t : touched_) {
      for (const std::uint32_t v : mesh.triangles[t]) on_touched[v] = true;
    }
    std::vector<EdgeSide> sides;
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
      if (samples_.lattice_sizes[t] < 3) continue;
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
        if (!touched_flag_[t] && !(on_touched[a] && on_touched[b])) continue;
        sides.push_back({std::min(a, b), std::max(a, b), static_cast<std::uint32_t>(t), k});
      }
    }
    const auto key = [](const EdgeSide& s) { return std::array{s.v0, s.v1, s.triangle}; };
    std::sort(sides.begin(), sides.end(),
              [&](const EdgeSide& x, const EdgeSide& y) { return key(x) < key(y); });
    for (std::size_t first = 0; first < sides.size();) {
      std::size_t last = first + 1;
      bool touched = touched_flag_[sides[first].triangle];
      while (last < sides.size() && sides[last].v0 == sides[first].v0 &&
             sides[last].v1 == sides[first].v1) {
        touched = touched || touched_flag_[sides[last].triangle];
        ++last;
      }
      if (last - first > 1 && touched) {
        connect_along_edge(std::span(sides).subspan(first, last - first));
      }
      first = last;
    }
  }

  std::vector<ErrorRegion> regions() {
    std::vector<ErrorRegion> regions;
    region_of_root_.assign(members_.size(), kUnassigned);
    for (const std::uint64_t s : members_) {
      std::size_t& index = region_of_root_[root(s)];
      if (index == kUnassigned) {
        index = regions.size();
        regions.push_back({kind(s), 0, {d_[s], s, samples_.positions[s]}, 0, {}});
      }
      add_sample(regions[index], s);
    }
    add_areas(regions);
    order_.resize(regions.size());
    for (std::size_t k = 0; k < order_.size(); ++k) order_[k] = k;
    std::sort(order_.begin(), order_.end(), [&](std::size_t a, std::size_t b) {
      const ErrorRegion &x = regions[a], &y = regions[b];
      return x.area != y.area ? x.area > y.area : x.extreme.sample < y.extreme.sample;
    });
    std::vector<ErrorRegion> sorted;
    sorted.reserve(regions.size());
    for (const std::size_t k : order_) sorted.push_back(regions[k]);
    return sorted;
  }

  // Per sample: 1 + its region's place in the order regions() returned, or kNoRegion.
  std::vector<std::uint32_t> sample_regions() {
    std::vector<std::uint32_t> rank(order_.size());
    for (std::size_t k = 0; k < order_.size(); ++k) {
      rank[order_[k]] = static_cast<std::uint32_t>(k + 1);
    }
    std::vector<std::uint32_t> labels(d_.size(), kNoRegion);
    for (const std::uint64_t s : members_) labels[s] = rank[region_of_root_[root(s)]];
    return labels;
  }

 private:
  static constexpr std::size_t kUnassigned = ~std::size_t{0};

  RegionKind kind(std::uint64_t s) const { return static_cast<RegionKind>(kind_[s] - 1); }
  std::uint64_t root(std::uint64_t s) { return sets_.find(member_[s]); }

  // The triangles with an out-of-tolerance sample (corner, edge or interior point), in
  // mesh order.
  void find_touched_triangles() {
    const std::size_t triangles = samples_.lattice_sizes.size();
    touched_flag_.assign(triangles, 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, triangles, kBlock), [&](const auto& r) {
      for (std::size_t t = r.begin(); t != r.end(); ++t) touched_flag_[t] = touched(t);
    });
    touched_ = kept_indices<std::uint32_t>(triangles,
                                           [&](std::size_t t) { return touched_flag_[t] != 0; });
  }

  std::uint8_t touched(std::size_t t) const {
    const std::uint32_t n = samples_.lattice_sizes[t];
    if (n < 2) return 0;
    for (const std::uint32_t v : samples_.mesh.triangles[t]) {
      if (kind_[samples_.vertex_sample[v]] != kWithin) return 1;
    }
    const std::uint64_t first = samples_.first_interior_sample[t];
    const std::uint64_t end = first + lattice_interior_count(n);
    for (std::uint64_t s = first; s < end; ++s) {
      if (kind_[s] != kWithin) return 1;
    }
    return 0;
  }

  void connect(std::uint64_t a, std::uint64_t b) {
    if (kind_[a] != kWithin && kind_[a] == kind_[b]) sets_.unite(member_[a], member_[b]);
  }

  // The lattice points strictly inside the edge, from all triangles on it, merged by
  // their exact rational parameter; neighbours in that order are connected.
  void connect_along_edge(std::span<const EdgeSide> sides) {
    std::vector<EdgePoint> points;
    for (const EdgeSide& side : sides) {
      const std::uint32_t n = samples_.lattice_sizes[side.triangle];
      const bool reversed = samples_.mesh.triangles[side.triangle][side.corner] != side.v0;
      for (std::uint32_t m = 1; m + 1 < n; ++m) {
        const auto [i, j] = edge_lattice_point(side.corner, m, n);
        points.push_back(
            {reversed ? n - 1 - m : m, n - 1, samples_.sample_at(side.triangle, i, j)});
      }
    }
    std::sort(points.begin(), points.end(), [](const EdgePoint& a, const EdgePoint& b) {
      const std::uint64_t left = a.step * b.steps, right = b.step * a.steps;
      return left != right ? left < right : a.sample < b.sample;
    });
    for (std::size_t k = 1; k < points.size(); ++k) connect(points[k - 1].sample, points[k].sample);
  }

  // Point m of the lattice edge that leaves corner k (A->B, B->C, C->A).
  static std::pair<std::uint32_t, std::uint32_t> edge_lattice_point(int k, std::uint32_t m,
                                                                    std::uint32_t n) {
    if (k == 0) return {m, 0};
    if (k == 1) return {n - 1 - m, m};
    return {0, n - 1 - m};
  }

  void add_sample(ErrorRegion& region, std::uint64_t s) const {
    ++region.samples;
    region.box.extend(samples_.positions[s]);
    const bool more_extreme = region.kind == RegionKind::excess ? d_[s] > region.extreme.value
                                                                : d_[s] < region.extreme.value;
    if (more_extreme) region.extreme = {d_[s], s, samples_.positions[s]};
  }

  ErrorRegion& region_of(std::vector<ErrorRegion>& regions, std::uint64_t s) {
    return regions[region_of_root_[root(s)]];
  }

  bool is(std::uint64_t s, RegionKind k) const { return kind_[s] == 1 + static_cast<KindCode>(k); }

  void add_areas(std::vector<ErrorRegion>& regions) {
    for (const std::uint32_t t : touched_) {
      const double area = lattice_triangle_area(samples_, t);
      for_each_lattice_triangle(
          samples_, t, [&](std::uint64_t a, std::uint64_t b, std::uint64_t c) {
            if (kind_[a] == kWithin && kind_[b] == kWithin && kind_[c] == kWithin) return;
            const LinearPatch patch = make_linear_patch(area, d_[a], d_[b], d_[c]);
            for (const std::uint64_t s : {a, b, c}) {
              if (is(s, RegionKind::excess)) {
                region_of(regions, s).area += area_above(patch, zone_.upper);
                break;
              }
            }
            for (const std::uint64_t s : {a, b, c}) {
              if (is(s, RegionKind::gouge)) {
                region_of(regions, s).area += area_below(patch, zone_.lower);
                break;
              }
            }
          });
    }
  }

  const SampleSet& samples_;
  std::span<const double> d_;
  Tolerance zone_;
  std::vector<KindCode> kind_;               // per sample
  Buffer<std::uint32_t> member_;             // per out-of-tolerance sample: its number
  Buffer<std::uint64_t> members_;            // the out-of-tolerance samples, ascending
  DisjointSets sets_{0};                     // over members_
  std::vector<std::uint8_t> touched_flag_;   // per triangle
  Buffer<std::uint32_t> touched_;            // triangles with an out-of-tolerance sample
  std::vector<std::size_t> region_of_root_;  // per member: its region when it is a root
  std::vector<std::size_t> order_;           // regions in reported order (largest first)
};

}  // namespace

std::vector<ErrorRegion> find_error_regions(const SampleSet& samples, std::span<const double> d,
                                            const Tolerance& tolerance) {
  RegionBuilder builder(samples, d, tolerance);
  builder.connect_lattices();
  builder.connect_across_edges();
  return builder.regions();
}

RegionMap map_error_regions(const SampleSet& samples, std::span<const double> d,
                            const Tolerance& tolerance) {
  RegionBuilder builder(samples, d, tolerance);
  builder.connect_lattices();
  builder.connect_across_edges();
  RegionMap map;
  map.regions = builder.regions();
  map.sample_region = builder.sample_regions();
  return map;
}

}  // namespace ncv
