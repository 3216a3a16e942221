#include "runners/grid_runner.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>

#include "files/grid_file.hpp"
#include "mesh/mesh_reader.hpp"
#include "util/input_bytes.hpp"
#include "util/memory_guard.hpp"
#include "util/stopwatch.hpp"

namespace ncv {

IndexedSurface index_surface(std::shared_ptr<const Mesh> mesh, const std::string& source,
                             const GridOptions& options, SurfaceHolding holding) {
  Stopwatch clock;
  IndexedSurface indexed;
  indexed.reference =
      index_reference(std::move(mesh), source, options, &indexed.statistics, holding);
  indexed.seconds = clock.seconds();
  return indexed;
}

namespace {

// The loops logged one line each; the grid file's header lists the first 100.
constexpr std::size_t kLoggedLoops = 10;

std::string format_point(Vec3 p) {
  return fmt::format("({:.6g}, {:.6g}, {:.6g})", p[0], p[1], p[2]);
}

// Where an open nominal is open: its holes, each with its length and where it is, so a
// missing face can be found in CAD (docs/METHOD.md: an open nominal is signed by the
// winding number).
void log_boundary_loops(const IndexedReference& g) {
  const ReferenceSurface& surface = *g.surface;
  const TopologyReport& t = surface.topology();
  if (t.boundary_edges == 0) return;
  if (!surface.on_halfedges()) {
    spdlog::info(
        "{}: {} boundary edges; loops not traced (OpenMesh cannot hold this mesh as it is)",
        g.source, t.boundary_edges);
    return;
  }
  const std::uint64_t count = surface.boundary_loop_count();
  spdlog::info("{}: open: {} boundary loop{} of {} edges in all", g.source, count,
               count == 1 ? "" : "s", t.boundary_edges);
  const auto& loops = surface.boundary_loops();
  for (std::size_t i = 0; i < std::min(loops.size(), kLoggedLoops); ++i) {
    const BoundaryLoop& loop = loops[i];
    spdlog::info("  loop {}: {} edges, length {:.6g}, through {}, box {} to {}", i + 1, loop.edges,
                 loop.length, format_point(loop.start), format_point(loop.box.min),
                 format_point(loop.box.max));
  }
  if (count > kLoggedLoops) {
    spdlog::info(
        "  and {} more loops (the grid file's header lists the first {}: ncverify inspect)",
        count - kLoggedLoops, std::min<std::uint64_t>(count, 100));
  }
}

}  // namespace

void log_grid(const IndexedSurface& indexed) {
  const IndexedReference& g = indexed.reference;
  const GridStatistics& s = indexed.statistics;
  const TopologyReport& t = g.surface->topology();
  spdlog::info(
      "{}: {} triangles, {} vertices; closed: {}, manifold: {}, consistently oriented: "
      "{}; sign by {}",
      g.source, g.mesh->triangle_count(), g.mesh->vertex_count(), t.closed() ? "yes" : "no",
      t.manifold() ? "yes" : "no", t.consistently_oriented() ? "yes" : "no",
      name_of(kSignMethodNames, g.surface->automatic_sign_method()));
  log_boundary_loops(g);
  spdlog::debug(
      "{}: {} edges, {} boundary, {} used by three or more triangles, {} misoriented; {} "
      "non-manifold vertices, {} degenerate and {} duplicate triangles; signed volume {} "
      "(auto signs by the pseudonormal only for a closed, consistently oriented surface)",
      g.source, t.edges, t.boundary_edges, t.non_manifold_edges, t.misoriented_edges,
      t.non_manifold_vertices, t.degenerate_triangles, t.duplicate_triangles, t.signed_volume);
  spdlog::debug(
      "grid cell size {} requested ({}), {} after {} growth steps; at most {} "
      "triangles in a cell",
      s.requested_cell_size, s.requested_cell_size == s.cell_size ? "kept" : "grown", s.cell_size,
      s.growth_steps, s.max_cell_triangles);
  spdlog::info(
      "grid {}×{}×{} = {} cells of {} ({} empty), {} references ({:.2f} per triangle), "
      "{}, built in {:.3f} s",
      s.dims[0], s.dims[1], s.dims[2], s.cells, s.cell_size, s.empty_cells, s.references,
      s.references_per_triangle, format_bytes(s.bytes), indexed.seconds);
  if (s.growth_steps > 0) {
    spdlog::info("cell size grown from {} to {} to keep memory bounded", s.requested_cell_size,
                 s.cell_size);
  }
}

// Output opened first and the report after the commit, as in `sample`.
void run_grid_build(const GridJob& job) {
  Stopwatch clock;
  OutputFile out(job.output, OutputKind::binary);
  IndexedSurface indexed = index_surface(std::make_shared<const Mesh>(read_mesh(job.mesh)),
                                         input_name(job.mesh), job.options);
  write_grid_file(indexed.reference, indexed.statistics, out);
  out.commit();
  indexed.seconds = clock.seconds();
  log_grid(indexed);
  spdlog::info("wrote {}", out.display_name());
}

}  // namespace ncv
