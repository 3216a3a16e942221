#include "render/display_mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include "sampling/lattice_triangles.hpp"

namespace ncv {

namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();
constexpr double kLargestJump = 1.0 / 32;  // of the colour range, across one collapsed edge

std::uint64_t lattice_mesh_triangles(const SampleSet& samples) {
  std::uint64_t total = 0;
  for (const std::uint32_t n : samples.lattice_sizes)
    total += n >= 2 ? lattice_triangle_count(n) : 1;
  return total;
}

bool is_corner(std::uint32_t i, std::uint32_t j, std::uint32_t n) {
  return (i == 0 && j == 0) || (i == n - 1 && j == 0) || (i == 0 && j == n - 1);
}

// A workpiece triangle that could be shown with its whole lattice, and why.
struct Candidate {
  std::uint32_t triangle;
  int tier;          // 2: holds the largest or smallest error; 1: an out-of-tolerance sample
  double departure;  // largest |lattice value - corners' interpolation|
  std::uint64_t cost;
};

std::vector<Candidate> telling_triangles(const DisplayMeshInput& in) {
  const SampleSet& s = in.samples;
  const auto [lo, hi] = std::minmax_element(in.d.begin(), in.d.end());
  const std::uint64_t worst[2] = {static_cast<std::uint64_t>(lo - in.d.begin()),
                                  static_cast<std::uint64_t>(hi - in.d.begin())};
  std::vector<Candidate> candidates;
  for (std::uint32_t t = 0; t < s.lattice_sizes.size(); ++t) {
    const std::uint32_t n = s.lattice_sizes[t];
    if (n < 3) continue;
    const double a = in.d[s.sample_at(t, 0, 0)], b = in.d[s.sample_at(t, n - 1, 0)],
                 c = in.d[s.sample_at(t, 0, n - 1)];
    Candidate candidate{t, 0, 0, lattice_triangle_count(n) - 1};
    for (std::uint32_t i = 0; i < n; ++i) {
      for (std::uint32_t j = 0; i + j < n; ++j) {
        if (is_corner(i, j, n)) continue;
        const std::uint64_t sample = s.sample_at(t, i, j);
        const double value = in.d[sample];
        const double linear = a + (b - a) * i / (n - 1) + (c - a) * j / (n - 1);
        candidate.departure = std::max(candidate.departure, std::abs(value - linear));
        if (sample == worst[0] || sample == worst[1]) candidate.tier = 2;
        if (in.tolerance && classify(value, *in.tolerance) != ToleranceClass::within) {
          candidate.tier = std::max(candidate.tier, 1);
        }
      }
    }
    if (candidate.tier > 0 || candidate.departure > 0) candidates.push_back(candidate);
  }
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
    if (x.tier != y.tier) return x.tier > y.tier;
    if (x.departure != y.departure) return x.departure > y.departure;
    return x.triangle < y.triangle;
  });
  return candidates;
}

// Builds an ErrorMesh from samples, each used sample one vertex.
class SampleMeshBuilder {
 public:
  explicit SampleMeshBuilder(const DisplayMeshInput& in)
      : in_(in),
        vertex_of_sample_(in.samples.sample_count(), kNone),
        vertex_of_corner_(in.samples.mesh.vertex_count(), kNone) {}

  void add_lattice(std::size_t t) {
    for_each_lattice_triangle(
        in_.samples, t, [&](std::uint64_t a, std::uint64_t b, std::uint64_t c) {
          out_.mesh.triangles.push_back({sample_vertex(a), sample_vertex(b), sample_vertex(c)});
        });
  }

  void add_corners(std::size_t t) {
    const Triangle& corners = in_.samples.mesh.triangles[t];
    out_.mesh.triangles.push_back(
        {corner_vertex(corners[0]), corner_vertex(corners[1]), corner_vertex(corners[2])});
  }

  ErrorMesh take() { return std::move(out_); }

 private:
  std::uint32_t add_vertex(Vec3 p, double value, std::uint32_t region) {
    out_.mesh.vertices.push_back(p);
    out_.values.push_back(value);
    out_.regions.push_back(region);
    return static_cast<std::uint32_t>(out_.mesh.vertices.size() - 1);
  }

  std::uint32_t sample_vertex(std::uint64_t s) {
    std::uint32_t& v = vertex_of_sample_[s];
    if (v == kNone) {
      v = add_vertex(in_.samples.positions[s], in_.d[s],
                     in_.sample_region.empty() ? kNoRegion : in_.sample_region[s]);
    }
    return v;
  }

  // A mesh vertex: its sample, or (scheme II) a vertex without a value.
  std::uint32_t corner_vertex(std::uint32_t v) {
    if (in_.samples.vertex_sample[v] != kNoSample)
      return sample_vertex(in_.samples.vertex_sample[v]);
    std::uint32_t& vertex = vertex_of_corner_[v];
    if (vertex == kNone) vertex = add_vertex(in_.samples.mesh.vertices[v], kNoValue, kNoRegion);
    return vertex;
  }

  const DisplayMeshInput& in_;
  ErrorMesh out_;
  std::vector<std::uint32_t> vertex_of_sample_;
  std::vector<std::uint32_t> vertex_of_corner_;
};

// --- A workpiece larger than the budget: vertex clustering with the features kept -------

int value_class(double value, const std::optional<Tolerance>& tolerance) {
  if (std::isnan(value)) return 3;
  return tolerance ? static_cast<int>(classify(value, *tolerance)) : 0;
}

// The vertices that stand for the others: one per grid cell, tolerance class and band of
// values (kLargestJump of the colour range); a vertex of a region or of a worst point
// stands for itself alone. The first vertex of each group (in index order) represents it,
// so the result does not depend on anything but the input.
class VertexClusters {
 public:
  VertexClusters(const Mesh& mesh, const VertexErrors& errors, const DisplayMeshInput& in)
      : mesh_(mesh), errors_(errors), in_(in), box_(bounding_box(mesh)) {
    const auto [lo, hi] = std::minmax_element(in.d.begin(), in.d.end());
    worst_ = {*lo, *hi};
    band_ = kLargestJump * (in.color_range.hi - in.color_range.lo);
  }

  // Each vertex's representative for cells of edge `cell`: the keys made in parallel, then
  // the first vertex of each found in an open-addressing table of vertex indices (with
  // std::unordered_map a clustering of the 626 k-vertex finishing part took 18-20 ms).
  std::vector<std::uint32_t> representatives(double cell) const {
    const std::size_t count = mesh_.vertex_count();
    std::vector<std::uint64_t> keys(count);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 4096), [&](const auto& range) {
      for (std::size_t v = range.begin(); v != range.end(); ++v) {
        keys[v] = key(static_cast<std::uint32_t>(v), cell);
      }
    });
    std::size_t mask = 15;
    while (mask < 2 * count) mask = 2 * mask + 1;
    // The multiplier spreads keys that differ in their low bits (neighbouring cells).
    const auto home = [&](std::size_t v) {
      return static_cast<std::size_t>((keys[v] * 0x9e3779b97f4a7c15ull) >> 24) & mask;
    };
    std::vector<std::uint32_t> first(mask + 1, kNone);
    std::vector<std::uint32_t> rep(count);
    // The table's slots are random accesses: each is requested kAhead vertices early.
    constexpr std::size_t kAhead = 16;
    for (std::uint32_t v = 0; v < count; ++v) {
      if (v + kAhead < count) __builtin_prefetch(&first[home(v + kAhead)]);
      std::size_t slot = home(v);
      while (first[slot] != kNone && keys[first[slot]] != keys[v]) slot = (slot + 1) & mask;
      if (first[slot] == kNone) first[slot] = v;
      rep[v] = first[slot];
    }
    return rep;
  }

 private:
  std::uint64_t key(std::uint32_t v, double cell) const {
    const double value = errors_.values[v];
    if (errors_.regions[v] != kNoRegion || value == worst_[0] || value == worst_[1]) {
      return std::uint64_t{1} << 63 | v;
    }
    std::uint64_t key = 0;
    for (int axis = 0; axis < 3; ++axis) {
      const double offset = (mesh_.vertices[v][axis] - box_.min[axis]) / cell;
      key = key << 16 | (static_cast<std::uint64_t>(offset) & 0xffff);
    }
    const double band =
        band_ > 0 && !std::isnan(value) ? std::floor((value - in_.color_range.lo) / band_) : 0.0;
    key = key << 2 | static_cast<std::uint64_t>(value_class(value, in_.tolerance));
    return key << 8 | (static_cast<std::uint64_t>(std::clamp(band, 0.0, 255.0)) & 0xff);
  }

  const Mesh& mesh_;
  const VertexErrors& errors_;
  const DisplayMeshInput& in_;
  BoundingBox box_;
  std::array<double, 2> worst_{};
  double band_ = 0;
};

bool survives(const Triangle& t, const std::vector<std::uint32_t>& rep) {
  const Triangle r{rep[t[0]], rep[t[1]], rep[t[2]]};
  return r[0] != r[1] && r[1] != r[2] && r[2] != r[0];
}

// How many triangles survive the clustering: counted in parallel, as the search for the cell
// size asks it at every step it tries (made only for the size chosen).
std::size_t surviving_count(const Mesh& mesh, const std::vector<std::uint32_t>& rep) {
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, mesh.triangle_count(), 1 << 14), std::size_t{0},
      [&](const tbb::blocked_range<std::size_t>& range, std::size_t count) {
        for (std::size_t t = range.begin(); t != range.end(); ++t) {
          count += survives(mesh.triangles[t], rep) ? 1 : 0;
        }
        return count;
      },
      std::plus<>());
}

// The triangles that survive the clustering, on the representatives' vertices.
std::vector<Triangle> clustered_triangles(const Mesh& mesh, const std::vector<std::uint32_t>& rep) {
  std::vector<Triangle> triangles;
  for (const Triangle& t : mesh.triangles) {
    if (survives(t, rep)) triangles.push_back({rep[t[0]], rep[t[1]], rep[t[2]]});
  }
  return triangles;
}

// Cells grow by steps of 1.25 from the size that would give about `budget` triangles on an
// even surface, to the first size that meets the budget (or spans the part: what is left
// is features). The size is searched by doubling the number of steps, then bisecting: the
// features kept whole make the count fall slowly, and on the finishing part the 14 steps
// one by one took 280 ms of the HTML page. The workpiece's mesh and its vertex errors are read
// in place (a copy of the 1.25 M-triangle finishing part's mesh took 28 ms of its page).
ErrorMesh clustered(const Mesh& mesh, const VertexErrors& errors, const DisplayMeshInput& in,
                    std::uint64_t budget) {
  const VertexClusters clusters(mesh, errors, in);
  const double diagonal = bounding_box(mesh).diagonal();
  std::vector<double> cells{
      std::max(std::sqrt(2 * surface_area(mesh) / static_cast<double>(budget)), diagonal / 60000)};
  while (cells.back() < diagonal) cells.push_back(cells.back() * 1.25);
  std::vector<std::uint32_t> rep;
  std::size_t last = 0;  // the step rep is of
  const auto meets = [&](std::size_t step) {
    last = step;
    rep = clusters.representatives(cells[step]);
    return surviving_count(mesh, rep) <= budget || step + 1 == cells.size();
  };
  std::size_t over = 0, within = 0;  // a step over the budget (or none), one within it
  if (!meets(0)) {
    for (within = 1; !meets(within); within = std::min(2 * within, cells.size() - 1)) {
      over = within;
    }
    while (within - over > 1) {
      const std::size_t middle = over + (within - over) / 2;
      (meets(middle) ? within : over) = middle;
    }
    if (last != within) meets(within);
  }
  std::vector<Triangle> triangles = clustered_triangles(mesh, rep);
  ErrorMesh out;
  std::vector<std::uint32_t> renumbered(mesh.vertex_count(), kNone);
  for (Triangle& t : triangles) {
    for (std::uint32_t& v : t) {
      if (renumbered[v] == kNone) {
        renumbered[v] = static_cast<std::uint32_t>(out.mesh.vertices.size());
        out.mesh.vertices.push_back(mesh.vertices[v]);
        out.values.push_back(errors.values[v]);
        out.regions.push_back(errors.regions[v]);
      }
      v = renumbered[v];
    }
  }
  out.mesh.triangles = std::move(triangles);
  return out;
}

}  // namespace

DisplayMesh make_display_mesh(const DisplayMeshInput& in, std::uint64_t budget) {
  const SampleSet& s = in.samples;
  DisplayMesh display;
  display.budget = budget;
  display.lattice_triangles = lattice_mesh_triangles(s);
  if (display.lattice_triangles <= budget) {
    display.mesh = lattice_error_mesh(s, in.d, in.sample_region);
    display.detail = DisplayDetail::every_sample;
    return display;
  }
  const std::uint64_t triangles = s.mesh.triangle_count();
  if (triangles > budget) {
    display.mesh = clustered(s.mesh, vertex_errors(s, in.d, in.sample_region), in, budget);
    display.detail = DisplayDetail::clustered;
    return display;
  }
  std::vector<bool> refined(triangles, false);
  std::uint64_t used = triangles;
  for (const Candidate& c : telling_triangles(in)) {
    if (used + c.cost > budget) continue;
    used += c.cost;
    refined[c.triangle] = true;
    ++display.refined_triangles;
  }
  SampleMeshBuilder builder(in);
  for (std::size_t t = 0; t < triangles; ++t) {
    if (refined[t]) {
      builder.add_lattice(t);
    } else {
      builder.add_corners(t);
    }
  }
  display.mesh = builder.take();
  display.detail = DisplayDetail::refined;
  return display;
}

std::string describe(const DisplayMesh& display) {
  const std::uint64_t shown = display.mesh.mesh.triangle_count();
  switch (display.detail) {
    case DisplayDetail::every_sample:
      return fmt::format("The view shows every sample: the sampling lattice's {} triangles.",
                         shown);
    case DisplayDetail::refined:
      return fmt::format(
          "The whole lattice ({} triangles) exceeds the view's budget of {} triangles: the "
          "view shows the workpiece's triangles at their corner samples, {} of them with "
          "their whole lattice (those holding the largest and smallest error, the "
          "out-of-tolerance samples and the strongest variation), {} triangles in all. "
          "Markers show the worst points and every region.",
          display.lattice_triangles, display.budget, display.refined_triangles, shown);
    case DisplayDetail::clustered:
      return fmt::format(
          "The workpiece exceeds the view's budget of {} triangles: the view shows it "
          "simplified to {} triangles (vertices merged within small cells, never across a "
          "tolerance limit or a jump of the error), every out-of-tolerance region and the "
          "worst points at full resolution; every vertex shows its own sample's value. "
          "Markers show the worst points and every region.",
          display.budget, shown);
  }
  return {};
}

}  // namespace ncv
