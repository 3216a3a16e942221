#include "statistics/error_regions.hpp"

#include <algorithm>
#include <array>
#include <optional>

#include "geometry/linear_patch.hpp"
#include "sampling/lattice_triangles.hpp"
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

std::optional<RegionKind> kind_of(double d, const Tolerance& zone) {
  switch (classify(d, zone)) {
    case ToleranceClass::excess:
      return RegionKind::excess;
    case ToleranceClass::gouge:
      return RegionKind::gouge;
    case ToleranceClass::within:
      break;
  }
  return std::nullopt;
}

class RegionBuilder {
 public:
  RegionBuilder(const SampleSet& samples, std::span<const double> d, const Tolerance& zone)
      : samples_(samples), d_(d), zone_(zone), sets_(d.size()) {
    kind_.reserve(d.size());
    for (double v : d) kind_.push_back(kind_of(v, zone));
  }

  void connect_lattices() {
    for (std::size_t t = 0; t < samples_.lattice_sizes.size(); ++t) {
      for_each_lattice_triangle(samples_, t,
                                [&](std::uint64_t a, std::uint64_t b, std::uint64_t c) {
                                  connect(a, b);
                                  connect(b, c);
                                  connect(c, a);
                                });
    }
  }

  // Only lattices of size >= 3 put samples inside an edge; the corners are shared already.
  void connect_across_edges() {
    std::vector<EdgeSide> sides;
    const Mesh& mesh = samples_.mesh;
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
      if (samples_.lattice_sizes[t] < 3) continue;
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
        sides.push_back({std::min(a, b), std::max(a, b), static_cast<std::uint32_t>(t), k});
      }
    }
    const auto key = [](const EdgeSide& s) { return std::array{s.v0, s.v1, s.triangle}; };
    std::sort(sides.begin(), sides.end(),
              [&](const EdgeSide& x, const EdgeSide& y) { return key(x) < key(y); });
    for (std::size_t first = 0; first < sides.size();) {
      std::size_t last = first + 1;
      while (last < sides.size() && sides[last].v0 == sides[first].v0 &&
             sides[last].v1 == sides[first].v1) {
        ++last;
      }
      if (last - first > 1) connect_along_edge(std::span(sides).subspan(first, last - first));
      first = last;
    }
  }

  std::vector<ErrorRegion> regions() {
    std::vector<ErrorRegion> regions;
    region_of_root_.assign(d_.size(), kUnassigned);
    for (std::uint64_t s = 0; s < d_.size(); ++s) {
      if (!kind_[s]) continue;
      std::size_t& index = region_of_root_[sets_.find(s)];
      if (index == kUnassigned) {
        index = regions.size();
        regions.push_back({*kind_[s], 0, {d_[s], s, samples_.positions[s]}, 0, {}});
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
    for (std::uint64_t s = 0; s < d_.size(); ++s) {
      if (kind_[s]) labels[s] = rank[region_of_root_[sets_.find(s)]];
    }
    return labels;
  }

 private:
  static constexpr std::size_t kUnassigned = ~std::size_t{0};

  void connect(std::uint64_t a, std::uint64_t b) {
    if (kind_[a] && kind_[a] == kind_[b]) sets_.unite(a, b);
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
    return regions[region_of_root_[sets_.find(s)]];
  }

  void add_areas(std::vector<ErrorRegion>& regions) {
    for (std::size_t t = 0; t < samples_.lattice_sizes.size(); ++t) {
      if (samples_.lattice_sizes[t] < 2) continue;
      const double area = lattice_triangle_area(samples_, t);
      for_each_lattice_triangle(
          samples_, t, [&](std::uint64_t a, std::uint64_t b, std::uint64_t c) {
            if (!kind_[a] && !kind_[b] && !kind_[c]) return;
            const LinearPatch patch = make_linear_patch(area, d_[a], d_[b], d_[c]);
            for (const std::uint64_t s : {a, b, c}) {
              if (kind_[s] == RegionKind::excess) {
                region_of(regions, s).area += area_above(patch, zone_.upper);
                break;
              }
            }
            for (const std::uint64_t s : {a, b, c}) {
              if (kind_[s] == RegionKind::gouge) {
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
  DisjointSets sets_;
  std::vector<std::optional<RegionKind>> kind_;
  std::vector<std::size_t> region_of_root_;  // per sample: its region when it is a root
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
