#include "mesh/vertex_order.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <tbb/parallel_for.h>

#include "geometry/morton_cells.hpp"
#include "util/bucket_positions.hpp"
#include "util/buffer.hpp"
#include "util/parallel_over.hpp"

namespace ncv {
namespace {

constexpr std::size_t kSampledTriangles = 4096;
// 6 bits an axis: 2^18 cells, a few vertices each on a large mesh; within a cell the old
// order stands.
constexpr int kBitsPerAxis = 6;
constexpr std::size_t kSortChunks = 4;

}  // namespace

bool vertices_scattered(const Mesh& mesh) {
  const std::size_t triangles = mesh.triangle_count();
  if (mesh.vertex_count() < kLeastVerticesToOrder || triangles == 0) return false;
  const std::size_t stride = std::max<std::size_t>(1, triangles / kSampledTriangles);
  std::vector<std::uint32_t> spans;
  for (std::size_t t = 0; t < triangles; t += stride) {
    const Triangle& c = mesh.triangles[t];
    spans.push_back(std::max({c[0], c[1], c[2]}) - std::min({c[0], c[1], c[2]}));
  }
  const auto middle = spans.begin() + static_cast<std::ptrdiff_t>(spans.size() / 2);
  std::nth_element(spans.begin(), middle, spans.end());
  return double(*middle) > double(mesh.vertex_count()) / 16;
}

// A stable counting sort by Morton cell (BucketPositions, chunks side by side): a vertex's
// place is fixed by its cell and, within it, by its old number, whatever the threads. A full
// sort by the 63-bit code took 26 ms of the read for the 620 k-vertex shuffled finishing part.
void order_vertices_spatially(Mesh& mesh) {
  const std::size_t vertices = mesh.vertex_count();
  const MortonCells cells(bounding_box(mesh), kBitsPerAxis);
  Buffer<std::uint32_t> cell(vertices);
  parallel_over(vertices, 1 << 14, [&](std::size_t v) { cell[v] = cells.cell(mesh.vertices[v]); });
  const auto chunk_vertices = [&](std::size_t c, auto&& visit) {
    for (std::size_t v = vertices * c / kSortChunks; v < vertices * (c + 1) / kSortChunks; ++v) {
      visit(v);
    }
  };
  BucketPositions<std::uint32_t, kSortChunks> positions(
      cells.count(), [&](std::size_t c, auto&& emit) {
        chunk_vertices(c, [&](std::size_t v) { emit(cell[v]); });
      });
  Buffer<std::uint32_t> renamed(vertices);
  std::vector<Vec3> ordered(vertices);
  tbb::parallel_for(std::size_t{0}, kSortChunks, [&](std::size_t c) {
    chunk_vertices(c, [&](std::size_t v) {
      const std::uint32_t at = positions.next(c, cell[v]);
      renamed[v] = at;
      ordered[at] = mesh.vertices[v];
    });
  });
  mesh.vertices = std::move(ordered);
  parallel_over(mesh.triangle_count(), 1 << 14, [&](std::size_t t) {
    for (std::uint32_t& corner : mesh.triangles[t]) corner = renamed[corner];
  });
}

}  // namespace ncv
