// The background grid of the closest-triangle search (paper §3.3) as plain arrays, so the
// grid-build command can write it and the distance command load it back.
//
// Frame: the grid lives in the nominal's local frame (ReferenceSurface::origin() is its zero).
// Cell (i, j, k) spans origin + [i, i+1] x [j, j+1] x [k, k+1] * cell_size; every bound is
// computed by cell_bound(origin[axis], cell_size, i) = origin[axis] + i * cell_size, in the
// builder and the search alike, so both agree on each bound to the last bit. Cells are
// numbered x fastest: (k * dims[1] + j) * dims[0] + i. Cell c lists the triangles
// cell_triangles[cell_offsets[c] .. cell_offsets[c + 1]) that touch it, ascending.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "geometry/bounding_box.hpp"
#include "reference/reference_surface.hpp"
#include "util/buffer.hpp"

namespace ncv {

// Coordinate of the lower face of cell index i along an axis whose cells start at `origin`:
// the one expression the builder, the grid and the search all compute bounds with, so they
// agree on each bound to the last bit.
inline double cell_bound(double origin, double cell_size, std::int64_t i) {
  return origin + static_cast<double>(i) * cell_size;
}

struct BackgroundGrid {
  Vec3 origin{0, 0, 0};
  double cell_size = 0;
  std::array<std::uint32_t, 3> dims{0, 0, 0};
  // cell count + 1; 32 bits, as the builder keeps the references below 2^32 and a grid file
  // with more is refused
  Buffer<std::uint32_t> cell_offsets;
  Buffer<std::uint32_t> cell_triangles;  // triangle indices, grouped by cell

  // dims[0] * dims[1] * dims[2], or nothing when it does not fit 64 bits. A loader calls
  // this on the header before sizing cell_offsets.
  static std::optional<std::uint64_t> checked_cell_count(const std::array<std::uint32_t, 3>& dims);

  std::uint64_t cell_count() const {
    return std::uint64_t{dims[0]} * std::uint64_t{dims[1]} * std::uint64_t{dims[2]};
  }
  std::uint64_t cell_index(std::uint32_t i, std::uint32_t j, std::uint32_t k) const {
    return (std::uint64_t{k} * dims[1] + j) * dims[0] + i;
  }
  double cell_bound(int axis, std::int64_t i) const {
    return ncv::cell_bound(origin[axis], cell_size, i);
  }
  BoundingBox bounds() const;

  // The fewest consecutive cells along `axis` (by cell_bound, as the builder placed the
  // triangles) that hold [low, high]: from the last whose lower face is at or below low to
  // the first whose upper face is at or above high (the grid's first or last cell for an
  // interval beyond it). A point on a face between two cells lies in both, and the builder
  // lists a triangle through it in both. False when the interval misses the grid.
  bool cells_meeting(int axis, double low, double high, std::int64_t& first,
                     std::int64_t& last) const;

  // Checks everything the search relies on to stay in bounds, so that a grid read from an
  // untrusted file cannot crash or hang it: finite origin, finite positive cell size, no
  // zero dimension, offsets sized cells + 1, starting at 0, monotone, ending at the list
  // size, lists strictly ascending, triangle indices below triangle_count, every triangle
  // in some cell (so a search always finds one). Throws InputError(source, ...) naming
  // the first fault. It cannot tell a list that misses a cell a triangle touches: that
  // would give wrong distances, not a crash; a file checksum, or rebuilding the grid
  // (tens of milliseconds for 17 k triangles), guards against it.
  void validate(std::size_t triangle_count, const std::string& source) const;
  // The above, plus: the grid box contains the nominal (in its local frame), which the
  // search's stopping rule assumes.
  void validate(const ReferenceSurface& nominal, const std::string& source) const;
};

}  // namespace ncv
