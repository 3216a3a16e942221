#include "search/grid_builder.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <utility>

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "geometry/triangle_box_overlap.hpp"
#include "util/bucket_positions.hpp"
#include "util/error.hpp"
#include "util/ordered_reduce.hpp"
#include "util/serial_sum.hpp"

namespace ncv {
namespace {

struct Layout {
  Vec3 origin{0, 0, 0};
  double h = 0;
  std::array<std::uint32_t, 3> dims{1, 1, 1};
  double slack = 0;

  double bound(int axis, std::int64_t i) const { return cell_bound(origin[axis], h, i); }
  std::uint64_t cell(std::int64_t i, std::int64_t j, std::int64_t k) const {
    return (static_cast<std::uint64_t>(k) * dims[1] + static_cast<std::uint64_t>(j)) * dims[0] +
           static_cast<std::uint64_t>(i);
  }
  std::int64_t clamped_index(int axis, double coordinate) const {
    const double index = std::floor((coordinate - origin[axis]) / h);
    return static_cast<std::int64_t>(std::clamp(index, 0.0, dims[axis] - 1.0));
  }
};

// Cells per axis (as doubles, they may not fit any integer yet) and the grid box centred on
// the part with at least h / 100 to spare on each side.
std::array<double, 3> cells_per_axis(const BoundingBox& part, double h) {
  std::array<double, 3> n{};
  for (int axis = 0; axis < 3; ++axis) {
    n[axis] = std::max(1.0, std::ceil(part.extent()[axis] / h + 0.02));
  }
  return n;
}

Layout make_layout(const BoundingBox& part, double h, const std::array<double, 3>& n) {
  Layout layout;
  layout.h = h;
  double scale = h;
  for (int axis = 0; axis < 3; ++axis) {
    layout.dims[axis] = static_cast<std::uint32_t>(n[axis]);
    layout.origin[axis] = part.min[axis] - 0.5 * (n[axis] * h - part.extent()[axis]);
    scale = std::max(
        {scale, std::fabs(layout.origin[axis]), std::fabs(layout.bound(axis, layout.dims[axis]))});
  }
  layout.slack = std::ldexp(scale, -30);
  return layout;
}

// The triangle's bounding box, and the cells of it grown by the slack, per axis [lo, hi].
struct CellSpan {
  BoundingBox box;
  std::array<std::int64_t, 3> lo{}, hi{};
  // How many cells the box spans: 1, 2 when it spans two along one axis and one along the
  // others, 0 otherwise.
  int cells_in_a_row() const {
    int extra = 0;
    for (int axis = 0; axis < 3; ++axis) {
      const std::int64_t span = hi[axis] - lo[axis];
      if (span > 1) return 0;
      extra += static_cast<int>(span);
    }
    return extra <= 1 ? 1 + extra : 0;
  }
};

CellSpan cell_span(const Layout& layout, const TriangleCorners& t) {
  CellSpan span;
  for (const Vec3& corner : t) span.box.extend(corner);
  for (int axis = 0; axis < 3; ++axis) {
    span.lo[axis] = layout.clamped_index(axis, span.box.min[axis] - layout.slack);
    span.hi[axis] = layout.clamped_index(axis, span.box.max[axis] + layout.slack);
  }
  return span;
}

// The candidate cells of one triangle: per column along the dominant axis k of its normal,
// the cells within the plane's span over the (grown) column, widened by the plane's
// possible direction error (relative 1e-4 of the triangle's size; is_degenerate_triangle
// excludes the triangles whose normal could be worse). Degenerate triangles take every
// cell of their bounding box.
class Candidates {
 public:
  Candidates(const Layout& layout, const TriangleCorners& t, const CellSpan& span)
      : layout_(layout), lo_(span.lo), hi_(span.hi) {
    normal_ = cross(t[1] - t[0], t[2] - t[0]);
    planar_ = !is_degenerate_triangle(t[0], t[1], t[2]);
    const Vec3 magnitude{std::fabs(normal_[0]), std::fabs(normal_[1]), std::fabs(normal_[2])};
    k_ = magnitude[0] >= magnitude[1] && magnitude[0] >= magnitude[2]
             ? 0
             : (magnitude[1] >= magnitude[2] ? 1 : 2);
    offset_ = dot(normal_, t[0]);
    const Vec3 extent = span.box.extent();
    pad_ = 1e-4 * std::max({extent[0], extent[1], extent[2]}) + 2 * layout.slack;
  }

  // visit(i, j, k) for every candidate cell, column by column.
  template <class Visit>
  void for_each(Visit&& visit) const {
    const int a = (k_ + 1) % 3;
    const int b = (k_ + 2) % 3;
    std::array<std::int64_t, 3> c{};
    for (c[a] = lo_[a]; c[a] <= hi_[a]; ++c[a]) {
      for (c[b] = lo_[b]; c[b] <= hi_[b]; ++c[b]) {
        const auto [first, last] = column(c[a], c[b]);
        for (c[k_] = first; c[k_] <= last; ++c[k_]) visit(c[0], c[1], c[2]);
      }
    }
  }

 private:
  std::pair<std::int64_t, std::int64_t> column(std::int64_t ia, std::int64_t ib) const {
    if (!planar_) return {lo_[k_], hi_[k_]};
    const int a = (k_ + 1) % 3;
    const int b = (k_ + 2) % 3;
    double low = std::numeric_limits<double>::infinity();
    double high = -low;
    for (std::int64_t da = 0; da <= 1; ++da) {
      for (std::int64_t db = 0; db <= 1; ++db) {
        const double xa = layout_.bound(a, ia + da) + (da ? 1 : -1) * layout_.slack;
        const double xb = layout_.bound(b, ib + db) + (db ? 1 : -1) * layout_.slack;
        const double xk = (offset_ - normal_[a] * xa - normal_[b] * xb) / normal_[k_];
        low = std::min(low, xk);
        high = std::max(high, xk);
      }
    }
    return {std::max(lo_[k_], layout_.clamped_index(k_, low - pad_)),
            std::min(hi_[k_], layout_.clamped_index(k_, high + pad_))};
  }

  const Layout& layout_;
  std::array<std::int64_t, 3> lo_{}, hi_{};
  Vec3 normal_{0, 0, 0};
  double offset_ = 0;
  double pad_ = 0;
  int k_ = 0;
  bool planar_ = true;
};

// Calls visit(cell) for every cell the triangle touches and returns how many candidates it
// counted. Where the grown box spans one cell, or two along one axis, the exact test would
// accept each of them (the corner with the least coordinate along that axis lies in the
// first grown cell, the one with the greatest in the second, by more than the rounding the
// slack covers), so they are taken without it: 56-89 % of the triangles of the bench's
// workpieces and nominals, both families (docs/PERFORMANCE.md).
template <class Visit>
std::uint64_t for_each_touched_cell(const Layout& layout, const TriangleCorners& t, Visit&& visit) {
  const CellSpan span = cell_span(layout, t);
  if (const int cells = span.cells_in_a_row()) {
    visit(layout.cell(span.lo[0], span.lo[1], span.lo[2]));
    if (cells == 2) visit(layout.cell(span.hi[0], span.hi[1], span.hi[2]));
    return static_cast<std::uint64_t>(cells);
  }
  const double half = 0.5 * layout.h + layout.slack;
  std::uint64_t candidates = 0;
  Candidates(layout, t, span).for_each([&](std::int64_t i, std::int64_t j, std::int64_t k) {
    ++candidates;
    const Vec3 centre{layout.origin[0] + (static_cast<double>(i) + 0.5) * layout.h,
                      layout.origin[1] + (static_cast<double>(j) + 0.5) * layout.h,
                      layout.origin[2] + (static_cast<double>(k) + 0.5) * layout.h};
    if (triangle_box_overlap(centre, {half, half, half}, t[0], t[1], t[2])) {
      visit(layout.cell(i, j, k));
    }
  });
  return candidates;
}

// The cell size grown until the cells fit their budget.
Layout layout_within_cell_budget(const BoundingBox& part, double& h, double cell_budget,
                                 GridStatistics& stats) {
  for (;; ++stats.growth_steps) {
    const std::array<double, 3> n = cells_per_axis(part, h);
    const double cells = n[0] * n[1] * n[2];
    if (cells <= cell_budget) return make_layout(part, h, n);
    h *= std::max(kGrowth, std::cbrt(cells / cell_budget));
  }
}

// Triangle-major references in fixed chunks of triangles (so the result does not depend on
// the thread count): chunk c holds, for its triangles in order, the cells each touches in
// ascending candidate order, and how many. One exact test per candidate.
struct ReferenceChunk {
  std::vector<std::uint32_t> cells;
  std::vector<std::uint32_t> counts;  // per triangle of the chunk
};

constexpr std::size_t kChunkTriangles = 4096;

// The chunks, or nothing when the triangles have more than `budget` candidates in all. A
// chunk stops (and none starts) once the candidates it counted and those the others added
// exceed the budget, and adds its count when it ends: a part of the total beyond the budget
// means the total is, so the answer depends on the total alone, not on the threads. The
// references held meanwhile stay within the budget but for one triangle's per thread.
std::optional<std::vector<ReferenceChunk>> touched_cells(const ReferenceSurface& nominal,
                                                         const Layout& layout,
                                                         std::uint64_t budget) {
  const std::size_t triangles = nominal.triangle_count();
  std::vector<ReferenceChunk> chunks((triangles + kChunkTriangles - 1) / kChunkTriangles);
  std::atomic<std::uint64_t> candidates{0};
  tbb::parallel_for(std::size_t{0}, chunks.size(), [&](std::size_t c) {
    ReferenceChunk& chunk = chunks[c];
    const std::size_t end = std::min(triangles, (c + 1) * kChunkTriangles);
    chunk.counts.reserve(end - c * kChunkTriangles);
    std::uint64_t tested = 0;
    for (std::size_t t = c * kChunkTriangles; t < end; ++t) {
      if (tested + candidates.load(std::memory_order_relaxed) > budget) break;
      const std::size_t before = chunk.cells.size();
      tested += for_each_touched_cell(layout, nominal.corners(t), [&](std::uint64_t cell) {
        chunk.cells.push_back(static_cast<std::uint32_t>(cell));
      });
      chunk.counts.push_back(static_cast<std::uint32_t>(chunk.cells.size() - before));
    }
    chunk.cells.shrink_to_fit();
    candidates.fetch_add(tested, std::memory_order_relaxed);
  });
  if (candidates.load() > budget) return std::nullopt;
  return chunks;
}

// Counting sort of the references by cell, each cell's list in triangle order, the chunks in
// kSortGroups fixed groups side by side (BucketPositions; one serial pass took 23-31 ms of the
// finishing workpiece's grid, 2.4 M references into 2.6 M cells).
constexpr std::size_t kSortGroups = 2;

void fill_cell_lists(BackgroundGrid& grid, const std::vector<ReferenceChunk>& chunks) {
  // visit(cell, triangle) for every reference of group g's chunks, in triangle order.
  const auto for_each_reference = [&](std::size_t g, auto&& visit) {
    for (std::size_t c = chunks.size() * g / kSortGroups; c < chunks.size() * (g + 1) / kSortGroups;
         ++c) {
      auto t = static_cast<std::uint32_t>(c * kChunkTriangles);
      std::size_t r = 0;
      for (const std::uint32_t count : chunks[c].counts) {
        for (std::uint32_t k = 0; k < count; ++k, ++r) visit(chunks[c].cells[r], t);
        ++t;
      }
    }
  };
  BucketPositions<std::uint32_t, kSortGroups> positions(
      grid.cell_count(), [&](std::size_t g, auto&& emit) {
        for_each_reference(g, [&](std::uint32_t cell, std::uint32_t) { emit(cell); });
      });
  grid.cell_triangles.resize(positions.starts().back());
  tbb::parallel_for(std::size_t{0}, kSortGroups, [&](std::size_t g) {
    for_each_reference(g, [&](std::uint32_t cell, std::uint32_t t) {
      grid.cell_triangles[positions.next(g, cell)] = t;
    });
  });
  grid.cell_offsets = positions.take_starts();
}

struct CellSizes {
  std::uint64_t empty = 0, largest = 0;
};

void summarise(const BackgroundGrid& grid, std::size_t triangles, GridStatistics& stats) {
  stats.dims = grid.dims;
  stats.cells = grid.cell_count();
  stats.references = grid.cell_triangles.size();
  stats.references_per_triangle =
      static_cast<double>(stats.references) / static_cast<double>(triangles);
  const CellSizes sizes = ordered_reduce(
      stats.cells, std::size_t{1} << 16, CellSizes{},
      [&](std::size_t begin, std::size_t end) {
        CellSizes part;
        for (std::size_t c = begin; c < end; ++c) {
          const std::uint64_t size = grid.cell_offsets[c + 1] - grid.cell_offsets[c];
          part.empty += size == 0;
          part.largest = std::max(part.largest, size);
        }
        return part;
      },
      [](CellSizes& into, const CellSizes& part) {
        into.empty += part.empty;
        into.largest = std::max(into.largest, part.largest);
      });
  stats.empty_cells = sizes.empty;
  stats.max_cell_triangles = sizes.largest;
  stats.bytes = grid.cell_offsets.size() * sizeof(std::uint32_t) +
                grid.cell_triangles.size() * sizeof(std::uint32_t);
  stats.cell_size = grid.cell_size;
}

double paper_cell_size(const ReferenceSurface& nominal) {
  const MeshCorners corners = nominal.corners();
  const double area = serial_sum(corners.size(), [&](std::size_t k) {
    const TriangleCorners t = corners[k];
    return 0.5 * norm(cross(t[1] - t[0], t[2] - t[0]));
  });
  const auto triangles = static_cast<double>(nominal.triangle_count());
  const double mean_area = area / triangles;
  if (mean_area > 0) return std::sqrt(4.0 * mean_area / std::sqrt(3.0));
  const double diagonal = nominal.local_bounds().diagonal();
  return diagonal > 0 ? diagonal / std::cbrt(triangles) : 1.0;
}

// The smallest cell edge (to 1 %) at which the part's box spans at most `cells` cells: from
// the box's volume over the count, an axis thinner than the cell counting as one layer (a
// flat part's box, a straight one's), then grown past the layout's rounding up and padding.
// Zero for a box without extent.
double filling_cell_size(const BoundingBox& part, double cells) {
  const Vec3 extent = part.extent();
  std::array<double, 3> e{extent[0], extent[1], extent[2]};
  std::sort(e.begin(), e.end());
  double h = std::cbrt(e[0] * e[1] * e[2] / cells);
  if (!(h > 0 && e[0] >= h)) h = std::sqrt(e[1] * e[2] / cells);
  if (!(h > 0 && e[1] >= h)) h = e[2] / cells;
  if (!(h > 0)) return 0;
  const auto count = [&](double edge) {
    const std::array<double, 3> n = cells_per_axis(part, edge);
    return n[0] * n[1] * n[2];
  };
  while (count(h) > cells) h *= 1.01;
  return h;
}

}  // namespace

double default_cell_size(const ReferenceSurface& nominal) {
  const double paper = paper_cell_size(nominal);
  const double least =
      filling_cell_size(nominal.local_bounds(), static_cast<double>(kLeastDefaultCells));
  return least > 0 && least < paper ? least : paper;
}

BackgroundGrid build_background_grid(const ReferenceSurface& nominal, const GridOptions& options,
                                     GridStatistics* statistics) {
  if (options.cell_size != 0 && !(std::isfinite(options.cell_size) && options.cell_size > 0)) {
    throw UsageError(fmt::format("grid cell size {} is not a positive number", options.cell_size));
  }
  GridStatistics stats;
  stats.requested_cell_size =
      options.cell_size > 0 ? options.cell_size : default_cell_size(nominal);
  const auto triangles = static_cast<std::uint64_t>(nominal.triangle_count());
  const double cell_budget =
      static_cast<double>(std::max(kCellsPerTriangle * triangles, kMinCellBudget));
  // Below 2^32, so that the cell offsets fit 32 bits (16 a triangle would reach it at
  // kMaxReferenceTriangles).
  const std::uint64_t reference_budget =
      std::min<std::uint64_t>(std::max(kReferencesPerTriangle * triangles, kMinReferenceBudget),
                              std::numeric_limits<std::uint32_t>::max());
  const BoundingBox& part = nominal.local_bounds();
  // No axis can ever use more than 2^31 cells (the cell budget is below that), so a cell
  // smaller than the part's extent / 2^31 grows at once: the cell counts stay finite.
  const Vec3 extent = part.extent();
  double h =
      std::max(stats.requested_cell_size, std::max({extent[0], extent[1], extent[2]}) * 0x1p-31);
  for (;; ++stats.growth_steps, h *= kGrowth) {
    const Layout layout = layout_within_cell_budget(part, h, cell_budget, stats);
    std::optional<std::vector<ReferenceChunk>> chunks =
        touched_cells(nominal, layout, reference_budget);
    if (!chunks) continue;
    BackgroundGrid grid;
    grid.origin = layout.origin;
    grid.cell_size = layout.h;
    grid.dims = layout.dims;
    fill_cell_lists(grid, *chunks);
    summarise(grid, nominal.triangle_count(), stats);
    if (statistics) *statistics = stats;
    return grid;
  }
}

}  // namespace ncv
