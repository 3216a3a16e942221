#include "ncgen/rtin.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ncv::gen {
namespace {

// The split samples at half-size h come in three kinds: midpoints of horizontal or vertical
// hypotenuses 2h long, and centres of 2h squares whose diagonal is the hypotenuse.
enum class Split { horizontal, vertical, diagonal };
constexpr Split all_splits[] = {Split::horizontal, Split::vertical, Split::diagonal};

struct Point {
  int i = 0;
  int j = 0;
};

// Calls visit(i, j) for every split sample of one kind at half-size h, rows in parallel.
template <typename Visit>
void for_each_split(const Grid& grid, int h, Split kind, const Visit& visit) {
  const int row0 = kind == Split::horizontal ? 0 : h;
  const int col0 = kind == Split::vertical ? 0 : h;
  const int rows = (grid.cells_y() - row0) / (2 * h) + 1;
  const int last_col = grid.cells_x();
  tbb::parallel_for(tbb::blocked_range<int>(0, rows), [&](const tbb::blocked_range<int>& range) {
    for (int row = range.begin(); row < range.end(); ++row) {
      const int j = row0 + 2 * h * row;
      for (int i = col0; i <= last_col; i += 2 * h) visit(i, j);
    }
  });
}

// Diagonals run from the square corner that is an odd multiple of 2h in both coordinates
// (the right-angle corner of the parent triangle) to the opposite corner: the bintree
// recursion from the tile roots produces exactly these.
std::array<Point, 2> hypotenuse(int i, int j, int h, Split kind) {
  if (kind == Split::horizontal) return {{{i - h, j}, {i + h, j}}};
  if (kind == Split::vertical) return {{{i, j - h}, {i, j + h}}};
  const int sx = ((i + h) / (2 * h)) % 2 == 1 ? 1 : -1;
  const int sy = ((j + h) / (2 * h)) % 2 == 1 ? 1 : -1;
  return {{{i + sx * h, j + sy * h}, {i - sx * h, j - sy * h}}};
}

float chord_error(const Grid& grid, const std::vector<float>& heights, int i, int j, int h,
                  Split kind) {
  const auto [a, b] = hypotenuse(i, j, h, kind);
  const double za = heights[grid.index(a.i, a.j)];
  const double zb = heights[grid.index(b.i, b.j)];
  const double zm = heights[grid.index(i, j)];
  const double run = 2.0 * h * grid.spacing * (kind == Split::diagonal ? std::numbers::sqrt2 : 1);
  return static_cast<float>(std::abs(zm - 0.5 * (za + zb)) * run / std::hypot(run, zb - za));
}

// Children of a split sample: the hypotenuse midpoints of the two (or four, for a diamond)
// triangles its split creates.
std::array<Point, 4> child_offsets(int h, Split kind) {
  if (kind == Split::diagonal) return {{{-h, 0}, {h, 0}, {0, -h}, {0, h}}};
  const int q = h / 2;
  return {{{-q, -q}, {q, -q}, {-q, q}, {q, q}}};
}

void raise_to_children(const Grid& grid, std::vector<float>& errors, int i, int j,
                       const std::array<Point, 4>& offsets) {
  float error = errors[grid.index(i, j)];
  for (const Point& o : offsets) {
    if (grid.contains(i + o.i, j + o.j)) {
      error = std::max(error, errors[grid.index(i + o.i, j + o.j)]);
    }
  }
  errors[grid.index(i, j)] = error;
}

// Triangles of a split sample's diamond that lie inside the grid.
int diamond_size(const Grid& grid, int i, int j, Split kind) {
  if (kind == Split::horizontal && (j == 0 || j == grid.cells_y())) return 1;
  if (kind == Split::vertical && (i == 0 || i == grid.cells_x())) return 1;
  return 2;
}

class Extractor {
 public:
  Extractor(const Grid& grid, const std::vector<float>& errors, float tolerance,
            std::vector<GridTriangle>& out)
      : grid_(grid), errors_(errors), tolerance_(tolerance), out_(out) {}

  // Triangle (a, b, c): hypotenuse a-b, right angle at c. Splitting keeps the orientation.
  void refine(Point a, Point b, Point c) {
    if (std::abs(a.i - c.i) + std::abs(a.j - c.j) > 1) {
      const Point m{(a.i + b.i) / 2, (a.j + b.j) / 2};
      if (errors_[grid_.index(m.i, m.j)] > tolerance_) {
        refine(c, a, m);
        refine(b, c, m);
        return;
      }
    }
    out_.push_back({grid_.index(a.i, a.j), grid_.index(b.i, b.j), grid_.index(c.i, c.j)});
  }

 private:
  const Grid& grid_;
  const std::vector<float>& errors_;
  float tolerance_;
  std::vector<GridTriangle>& out_;
};

std::array<Point, 3> counter_clockwise(Point a, Point b, Point c) {
  const long cross =
      static_cast<long>(b.i - a.i) * (c.j - a.j) - static_cast<long>(b.j - a.j) * (c.i - a.i);
  return cross > 0 ? std::array<Point, 3>{a, b, c} : std::array<Point, 3>{b, a, c};
}

// The two root triangles of a tile, split along the diagonal the bintree rule prescribes.
std::array<std::array<Point, 3>, 2> tile_roots(const Grid& grid, int tile_x, int tile_y) {
  const int h = grid.tile_cells() / 2;
  const auto [a, b] = hypotenuse(tile_x * 2 * h + h, tile_y * 2 * h + h, h, Split::diagonal);
  return {counter_clockwise(a, b, {a.i, b.j}), counter_clockwise(a, b, {b.i, a.j})};
}

}  // namespace

std::vector<float> chord_errors(const Grid& grid, const std::vector<float>& heights) {
  std::vector<float> errors(grid.sample_count(), 0.0f);
  for (int h = 1; h < grid.tile_cells(); h *= 2) {
    for (Split kind : all_splits) {
      for_each_split(grid, h, kind, [&](int i, int j) {
        errors[grid.index(i, j)] = chord_error(grid, heights, i, j, h, kind);
      });
    }
  }
  return errors;
}

void propagate_errors(const Grid& grid, std::vector<float>& errors) {
  // Level by level from the finest, so both triangles of every child diamond are final.
  for (int h = 1; h < grid.tile_cells(); h *= 2) {
    for (Split kind : all_splits) {
      if (kind != Split::diagonal && h == 1) continue;  // leaves: no split samples below
      const auto offsets = child_offsets(h, kind);
      for_each_split(grid, h, kind,
                     [&](int i, int j) { raise_to_children(grid, errors, i, j, offsets); });
    }
  }
}

std::vector<GridTriangle> rtin_triangles(const Grid& grid, const std::vector<float>& errors,
                                         float tolerance) {
  const int tiles = grid.tiles_x * grid.tiles_y;
  std::vector<std::vector<GridTriangle>> per_tile(static_cast<std::size_t>(tiles));
  tbb::parallel_for(0, tiles, [&](int tile) {
    Extractor extractor(grid, errors, tolerance, per_tile[static_cast<std::size_t>(tile)]);
    for (const auto& root : tile_roots(grid, tile % grid.tiles_x, tile / grid.tiles_x)) {
      extractor.refine(root[0], root[1], root[2]);
    }
  });
  std::vector<GridTriangle> triangles;
  for (const auto& part : per_tile) triangles.insert(triangles.end(), part.begin(), part.end());
  return triangles;
}

std::size_t rtin_triangle_count(const Grid& grid, const std::vector<float>& errors,
                                float tolerance) {
  // Every split replaces one triangle by two.
  std::size_t count = 2 * static_cast<std::size_t>(grid.tiles_x * grid.tiles_y);
  for (int h = 1; h < grid.tile_cells(); h *= 2) {
    for (Split kind : all_splits) {
      const int row0 = kind == Split::horizontal ? 0 : h;
      const int col0 = kind == Split::vertical ? 0 : h;
      for (int j = row0; j <= grid.cells_y(); j += 2 * h) {
        for (int i = col0; i <= grid.cells_x(); i += 2 * h) {
          if (errors[grid.index(i, j)] > tolerance) count += diamond_size(grid, i, j, kind);
        }
      }
    }
  }
  return count;
}

float tolerance_for_count(const Grid& grid, const std::vector<float>& errors, std::size_t target) {
  // Nearly every split adds a diamond of two triangles, so the k-th largest error is the
  // tolerance that keeps about 2k + roots triangles; splits on the grid's border add only
  // one, which a few rounds make up for.
  const std::size_t roots = 2 * static_cast<std::size_t>(grid.tiles_x * grid.tiles_y);
  std::vector<float> sorted = errors;
  const auto kth_largest = [&](std::size_t k) {
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(k - 1),
                     sorted.end(), std::greater<>());
    return std::nextafter(sorted[k - 1], 0.0f);
  };
  std::size_t splits =
      std::clamp<std::size_t>((std::max(target, roots) - roots) / 2, 1, sorted.size());
  float tolerance = kth_largest(splits);
  for (int round = 0; round < 4 && splits < sorted.size(); ++round) {
    const std::size_t count = rtin_triangle_count(grid, errors, tolerance);
    if (count >= target) break;
    splits = std::min(sorted.size(), splits + (target - count + 1) / 2);
    tolerance = kth_largest(splits);
  }
  return tolerance;
}

}  // namespace ncv::gen
