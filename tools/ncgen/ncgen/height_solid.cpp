#include "ncgen/height_solid.hpp"

#include <limits>
#include <unordered_map>

#include "ncgen/rtin.hpp"

namespace ncv::gen {
namespace {

constexpr std::uint32_t unused = std::numeric_limits<std::uint32_t>::max();

// Returns the mesh vertex of every sample, `unused` where the RTIN has none.
std::vector<std::uint32_t> add_top(const Grid& grid, const std::vector<float>& heights,
                                   const std::vector<GridTriangle>& triangles, ncv::Mesh& mesh) {
  std::vector<std::uint32_t> vertex_of_sample(grid.sample_count(), unused);
  const int row = grid.samples_x();
  for (const GridTriangle& t : triangles) {
    ncv::Triangle& out = mesh.triangles.emplace_back();
    for (int k = 0; k < 3; ++k) {
      std::uint32_t& v = vertex_of_sample[t[k]];
      if (v == unused) {
        v = static_cast<std::uint32_t>(mesh.vertices.size());
        const int i = static_cast<int>(t[k] % static_cast<std::uint32_t>(row));
        const int j = static_cast<int>(t[k] / static_cast<std::uint32_t>(row));
        mesh.vertices.push_back({grid.x(i), grid.y(j), heights[t[k]]});
      }
      out[k] = v;
    }
  }
  return vertex_of_sample;
}

// Border samples that carry a top vertex, counter-clockwise seen from +z.
std::vector<std::uint32_t> border_samples(const Grid& grid,
                                          const std::vector<std::uint32_t>& vertex_of_sample) {
  std::vector<std::uint32_t> border;
  const int nx = grid.cells_x();
  const int ny = grid.cells_y();
  const auto take = [&](int i, int j) {
    if (vertex_of_sample[grid.index(i, j)] != unused) border.push_back(grid.index(i, j));
  };
  for (int i = 0; i < nx; ++i) take(i, 0);
  for (int j = 0; j < ny; ++j) take(nx, j);
  for (int i = nx; i > 0; --i) take(i, ny);
  for (int j = ny; j > 0; --j) take(0, j);
  return border;
}

// The coarsest RTIN that has exactly the given border samples: forcing them and their
// ancestors splits nothing else.
std::vector<GridTriangle> bottom_triangles(const Grid& grid,
                                           const std::vector<std::uint32_t>& border) {
  std::vector<float> forced(grid.sample_count(), 0.0f);
  for (std::uint32_t s : border) forced[s] = 1.0f;
  propagate_errors(grid, forced);
  return rtin_triangles(grid, forced, 0.5f);
}

std::unordered_map<std::uint32_t, std::uint32_t> add_bottom(const Grid& grid,
                                                            const std::vector<GridTriangle>& tris,
                                                            double floor_z, ncv::Mesh& mesh) {
  std::unordered_map<std::uint32_t, std::uint32_t> vertex_of_sample;
  const auto row = static_cast<std::uint32_t>(grid.samples_x());
  for (const GridTriangle& t : tris) {
    ncv::Triangle out;
    for (int k = 0; k < 3; ++k) {
      const auto [it, fresh] =
          vertex_of_sample.try_emplace(t[k], static_cast<std::uint32_t>(mesh.vertices.size()));
      if (fresh) {
        mesh.vertices.push_back(
            {grid.x(static_cast<int>(t[k] % row)), grid.y(static_cast<int>(t[k] / row)), floor_z});
      }
      out[k] = it->second;
    }
    mesh.triangles.push_back({out[0], out[2], out[1]});  // facing -z
  }
  return vertex_of_sample;
}

void add_walls(const std::vector<std::uint32_t>& border, const std::vector<std::uint32_t>& top,
               const std::unordered_map<std::uint32_t, std::uint32_t>& bottom, ncv::Mesh& mesh) {
  for (std::size_t k = 0; k < border.size(); ++k) {
    const std::uint32_t p = border[k];
    const std::uint32_t q = border[(k + 1) % border.size()];
    const std::uint32_t bp = bottom.at(p);
    const std::uint32_t bq = bottom.at(q);
    // Walking the border counter-clockwise, the outside is on the right.
    mesh.triangles.push_back({bp, bq, top[q]});
    mesh.triangles.push_back({bp, top[q], top[p]});
  }
}

}  // namespace

ncv::Mesh height_field_solid(const Grid& grid, const std::vector<float>& heights,
                             const std::vector<float>& errors, float tolerance, double floor_z) {
  return close_height_field(grid, heights, rtin_triangles(grid, errors, tolerance), floor_z);
}

std::size_t closure_triangle_count(const Grid& grid, const std::vector<GridTriangle>& top) {
  std::vector<std::uint32_t> used(grid.sample_count(), unused);
  for (const GridTriangle& t : top) {
    for (const std::uint32_t s : t) used[s] = 0;
  }
  const std::vector<std::uint32_t> border = border_samples(grid, used);
  return 2 * border.size() + bottom_triangles(grid, border).size();
}

ncv::Mesh close_height_field(const Grid& grid, const std::vector<float>& heights,
                             const std::vector<GridTriangle>& top, double floor_z) {
  ncv::Mesh mesh;
  const std::vector<std::uint32_t> top_vertex = add_top(grid, heights, top, mesh);
  const std::vector<std::uint32_t> border = border_samples(grid, top_vertex);
  const auto bottom_vertex = add_bottom(grid, bottom_triangles(grid, border), floor_z, mesh);
  add_walls(border, top_vertex, bottom_vertex, mesh);
  return mesh;
}

}  // namespace ncv::gen
