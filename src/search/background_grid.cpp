#include "search/background_grid.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "util/error.hpp"

namespace ncv {
namespace {

void check_geometry(const BackgroundGrid& grid, const std::string& source) {
  if (!is_finite(grid.origin)) throw InputError(source, "grid origin is not finite");
  if (!std::isfinite(grid.cell_size) || !(grid.cell_size > 0)) {
    throw InputError(source,
                     fmt::format("grid cell size {} is not a positive number", grid.cell_size));
  }
  for (int axis = 0; axis < 3; ++axis) {
    if (grid.dims[axis] == 0) throw InputError(source, "grid has a zero dimension");
    if (!std::isfinite(grid.cell_bound(axis, grid.dims[axis]))) {
      throw InputError(source, "grid extends beyond the range of double");
    }
  }
}

void check_offsets(const BackgroundGrid& grid, const std::string& source) {
  const std::optional<std::uint64_t> cells = BackgroundGrid::checked_cell_count(grid.dims);
  if (!cells || grid.cell_offsets.empty() || grid.cell_offsets.size() - 1 != *cells) {
    throw InputError(
        source, fmt::format("grid has {} cell offsets for {} x {} x {} cells",
                            grid.cell_offsets.size(), grid.dims[0], grid.dims[1], grid.dims[2]));
  }
  if (grid.cell_offsets.front() != 0 || grid.cell_offsets.back() != grid.cell_triangles.size()) {
    throw InputError(source, "grid cell offsets do not span the triangle lists");
  }
  for (std::size_t c = 0; c + 1 < grid.cell_offsets.size(); ++c) {
    if (grid.cell_offsets[c] > grid.cell_offsets[c + 1]) {
      throw InputError(source, fmt::format("grid cell offsets decrease at cell {}", c));
    }
  }
}

void check_lists(const BackgroundGrid& grid, std::size_t triangle_count,
                 const std::string& source) {
  std::vector<bool> listed(triangle_count, false);
  for (std::size_t c = 0; c + 1 < grid.cell_offsets.size(); ++c) {
    for (std::uint64_t r = grid.cell_offsets[c]; r < grid.cell_offsets[c + 1]; ++r) {
      const std::uint32_t t = grid.cell_triangles[r];
      if (t >= triangle_count) {
        throw InputError(source,
                         fmt::format("grid cell {} lists triangle {} of {}", c, t, triangle_count));
      }
      if (r > grid.cell_offsets[c] && grid.cell_triangles[r - 1] >= t) {
        throw InputError(source, fmt::format("grid cell {} list is not strictly ascending", c));
      }
      listed[t] = true;
    }
  }
  const auto missing = std::find(listed.begin(), listed.end(), false);
  if (missing != listed.end()) {
    throw InputError(source,
                     fmt::format("grid lists triangle {} in no cell", missing - listed.begin()));
  }
}

}  // namespace

std::optional<std::uint64_t> BackgroundGrid::checked_cell_count(
    const std::array<std::uint32_t, 3>& dims) {
  std::uint64_t cells = 1;
  for (std::uint32_t d : dims) {
    if (d != 0 && cells > UINT64_MAX / d) return std::nullopt;
    cells *= d;
  }
  return cells;
}

bool BackgroundGrid::cells_meeting(int axis, double low, double high, std::int64_t& first,
                                   std::int64_t& last) const {
  const std::int64_t end = dims[axis];
  if (!(low <= cell_bound(axis, end)) || !(high >= cell_bound(axis, 0))) return false;
  // The quotients are within a cell of the answer; the bounds themselves decide.
  const auto estimate = [&](double x) {
    const double index = std::floor((x - origin[axis]) / cell_size);
    return static_cast<std::int64_t>(std::clamp(index, 0.0, static_cast<double>(end - 1)));
  };
  first = estimate(low);
  last = estimate(high);
  while (first > 0 && cell_bound(axis, first) > low) --first;
  while (first < end - 1 && cell_bound(axis, first + 1) <= low) ++first;
  while (last < end - 1 && cell_bound(axis, last + 1) < high) ++last;
  while (last > first && cell_bound(axis, last) >= high) --last;
  last = std::max(last, first);  // a point on a face: the cell above it
  return true;
}

BoundingBox BackgroundGrid::bounds() const {
  BoundingBox box;
  box.min = origin;
  box.max = {cell_bound(0, dims[0]), cell_bound(1, dims[1]), cell_bound(2, dims[2])};
  return box;
}

void BackgroundGrid::validate(std::size_t triangle_count, const std::string& source) const {
  check_geometry(*this, source);
  check_offsets(*this, source);
  check_lists(*this, triangle_count, source);
}

void BackgroundGrid::validate(const ReferenceSurface& nominal, const std::string& source) const {
  validate(nominal.triangle_count(), source);
  const BoundingBox grid_box = bounds();
  const BoundingBox& part = nominal.local_bounds();
  for (int axis = 0; axis < 3; ++axis) {
    if (part.min[axis] < grid_box.min[axis] || part.max[axis] > grid_box.max[axis]) {
      throw InputError(source, "grid does not cover the nominal mesh it was stored with");
    }
  }
}

}  // namespace ncv
