#include "files/grid_file.hpp"

#include <limits>

#include "files/mesh_arrays.hpp"
#include "geometry/point_json.hpp"
#include "util/parallel_over.hpp"

namespace ncv {
namespace {

nlohmann::json topology_meta(const TopologyReport& t) {
  return {{"closed", t.closed()},
          {"manifold", t.manifold()},
          {"consistently_oriented", t.consistently_oriented()},
          {"outward", t.outward()},
          {"edges", t.edges},
          {"boundary_edges", t.boundary_edges},
          {"non_manifold_edges", t.non_manifold_edges},
          {"misoriented_edges", t.misoriented_edges},
          {"non_manifold_vertices", t.non_manifold_vertices},
          {"degenerate_triangles", t.degenerate_triangles},
          {"duplicate_triangles", t.duplicate_triangles},
          {"signed_volume", t.signed_volume}};
}

// The loops a grid file lists (all are counted): enough to find every hole of a nominal
// that has a few, a bounded header for a triangle soup with one per triangle.
constexpr std::size_t kListedLoops = 100;

nlohmann::json boundary_loops_meta(const ReferenceSurface& s) {
  nlohmann::json listed = nlohmann::json::array();
  for (std::size_t i = 0; i < std::min(s.boundary_loops().size(), kListedLoops); ++i) {
    const BoundaryLoop& loop = s.boundary_loops()[i];
    listed.push_back({{"edges", loop.edges},
                      {"length", loop.length},
                      {"start", point_json(loop.start)},
                      {"bbox_min", point_json(loop.box.min)},
                      {"bbox_max", point_json(loop.box.max)}});
  }
  return {{"count", s.boundary_loop_count()}, {"listed", listed}};
}

nlohmann::json grid_meta(const IndexedReference& g, const GridStatistics& s) {
  const BoundingBox box = bounding_box(*g.mesh);
  const ReferenceSurface& nominal = *g.surface;
  return {{"tool", "ncverify " NCV_VERSION},
          {"nominal",
           {{"source", g.source},
            {"hash", hash_hex(g.hash)},
            {"vertices", g.mesh->vertex_count()},
            {"triangles", g.mesh->triangle_count()},
            {"bbox_min", {box.min[0], box.min[1], box.min[2]}},
            {"bbox_max", {box.max[0], box.max[1], box.max[2]}},
            {"topology", topology_meta(nominal.topology())},
            {"topology_from", nominal.on_halfedges() ? "openmesh" : "arrays"},
            {"boundary_loops", boundary_loops_meta(nominal)},
            {"flipped_to_outward", nominal.flipped()},
            {"sign_method", name_of(kSignMethodNames, nominal.automatic_sign_method())}}},
          {"grid",
           {{"origin_local", {g.grid.origin[0], g.grid.origin[1], g.grid.origin[2]}},
            {"cell_size", g.grid.cell_size},
            {"requested_cell_size", s.requested_cell_size},
            {"dims", g.grid.dims},
            {"cells", g.grid.cell_count()},
            {"empty_cells", s.empty_cells},
            {"references", g.grid.cell_triangles.size()},
            {"references_per_triangle", s.references_per_triangle}}}};
}

template <class T>
T number_field(const Container& c, const std::string& pointer) {
  const nlohmann::json& value = c.field(pointer);
  if (!value.is_number()) c.fail("metadata field " + pointer + " is not a number");
  return value.get<T>();
}

bool bool_field(const Container& c, const std::string& pointer) {
  const nlohmann::json& value = c.field(pointer);
  if (!value.is_boolean()) c.fail("metadata field " + pointer + " is not true or false");
  return value.get<bool>();
}

Vec3 point_field(const Container& c, const nlohmann::json& value) {
  if (!value.is_array() || value.size() != 3) c.fail("a boundary loop's point is malformed");
  Vec3 p;
  for (int k = 0; k < 3; ++k) {
    if (!value[k].is_number()) c.fail("a boundary loop's point is malformed");
    p[k] = value[k].get<double>();
  }
  return p;
}

TopologyReport read_topology(const Container& c) {
  const auto count = [&](const char* name) {
    return c.count(std::string("/nominal/topology/") + name);
  };
  TopologyReport t;
  t.triangles = c.count("/nominal/triangles");
  t.edges = count("edges");
  t.boundary_edges = count("boundary_edges");
  t.non_manifold_edges = count("non_manifold_edges");
  t.misoriented_edges = count("misoriented_edges");
  t.non_manifold_vertices = count("non_manifold_vertices");
  t.degenerate_triangles = count("degenerate_triangles");
  t.duplicate_triangles = count("duplicate_triangles");
  t.signed_volume = number_field<double>(c, "/nominal/topology/signed_volume");
  return t;
}

StoredSurface read_stored_surface(const Container& c, std::uint64_t vertices,
                                  std::uint64_t triangles) {
  StoredSurface s;
  s.topology = read_topology(c);
  s.flipped = bool_field(c, "/nominal/flipped_to_outward");
  s.boundary_loop_count = c.count("/nominal/boundary_loops/count");
  const nlohmann::json& listed = c.field("/nominal/boundary_loops/listed");
  if (!listed.is_array() || listed.size() > s.boundary_loop_count) {
    c.fail("the boundary loop list is malformed");
  }
  for (const nlohmann::json& item : listed) {
    if (!item.is_object() || !item.contains("edges") || !item["edges"].is_number_unsigned() ||
        !item.contains("length") || !item["length"].is_number()) {
      c.fail("the boundary loop list is malformed");
    }
    BoundaryLoop loop;
    loop.edges = item["edges"].get<std::uint64_t>();
    loop.length = item["length"].get<double>();
    loop.start = point_field(c, item.value("start", nlohmann::json()));
    loop.box.min = point_field(c, item.value("bbox_min", nlohmann::json()));
    loop.box.max = point_field(c, item.value("bbox_max", nlohmann::json()));
    s.boundary_loops.push_back(loop);
  }
  s.vertex_pseudonormals = c.get_points("vertex_pseudonormals", vertices);
  s.edge_pseudonormals = c.get_points("edge_pseudonormals", s.topology.edges);
  s.edge_of_slot = c.get<std::uint32_t, Buffer<std::uint32_t>>("edge_of_slot", 3 * triangles);
  return s;
}

}  // namespace

void write_grid_file(const IndexedReference& g, const GridStatistics& statistics, OutputFile& out) {
  ContainerWriter writer(FileKind::grid, kGridFormatVersion, grid_meta(g, statistics));
  writer.add_points("nominal_vertices", g.mesh->vertices);
  writer.add<std::uint32_t>("nominal_triangles", flat_indices(g.mesh->triangles),
                            {g.mesh->triangle_count(), 3});
  // The pseudonormals of a surface held on halfedges, so that `distance` need not rebuild
  // them (docs/FORMATS.md); one held on the arrays is rebuilt from them as before.
  if (g.surface->on_halfedges()) {
    const Pseudonormals& normals = g.surface->normals();
    writer.add_points("vertex_pseudonormals", normals.vertex);
    writer.add_points("edge_pseudonormals", normals.edge);
    writer.add<std::uint32_t>("edge_of_slot", normals.edge_of_slot, {g.mesh->triangle_count(), 3});
  }
  // Each cell's count rather than its offset: most cells of a dense mesh's grid are empty or
  // short, so a byte each instead of eight.
  Buffer<std::uint32_t> counts(g.grid.cell_count());
  parallel_over(counts.size(), 1 << 16, [&](std::size_t c) {
    counts[c] = static_cast<std::uint32_t>(g.grid.cell_offsets[c + 1] - g.grid.cell_offsets[c]);
  });
  writer.add_counts("cell_counts", counts);
  writer.add<std::uint32_t>("cell_triangles", g.grid.cell_triangles,
                            {g.grid.cell_triangles.size()});
  writer.write(out);
}

IndexedReference read_grid_file(const std::string& path) {
  return load_indexed_reference(Container::read(path, FileKind::grid, kGridFormatVersion));
}

IndexedReference load_indexed_reference(const Container& c) {
  IndexedReference g;
  const std::uint64_t V = c.count("/nominal/vertices"), T = c.count("/nominal/triangles");
  Mesh mesh;
  mesh.vertices = c.get_points("nominal_vertices", V);
  mesh.triangles = c.get_rows<std::uint32_t, Triangle>("nominal_triangles", T);
  if (!c.field("/nominal/hash").is_string()) c.fail("nominal hash is malformed");
  g.hash = parse_hash_hex(c.field("/nominal/hash").get<std::string>(), c);
  if (mesh_hash(mesh) != g.hash) c.fail("nominal mesh hash does not match");
  g.mesh = std::make_shared<const Mesh>(std::move(mesh));
  g.source = c.field("/nominal/source").is_string() ? c.field("/nominal/source").get<std::string>()
                                                    : std::string("nominal");
  const nlohmann::json& from = c.field("/nominal/topology_from");
  if (!from.is_string() || (from != "openmesh" && from != "arrays")) {
    c.fail("metadata field /nominal/topology_from is neither openmesh nor arrays");
  }
  if (from == "openmesh") {
    g.surface =
        std::make_unique<ReferenceSurface>(*g.mesh, c.source(), read_stored_surface(c, V, T));
  } else {
    g.surface = std::make_unique<ReferenceSurface>(*g.mesh, c.source(), SurfaceHolding::arrays);
  }

  const nlohmann::json& origin = c.field("/grid/origin_local");
  const nlohmann::json& dims = c.field("/grid/dims");
  if (!origin.is_array() || origin.size() != 3 || !dims.is_array() || dims.size() != 3) {
    c.fail("grid origin or dimensions are malformed");
  }
  for (int axis = 0; axis < 3; ++axis) {
    if (!origin[axis].is_number() || !dims[axis].is_number_unsigned() ||
        dims[axis].get<std::uint64_t>() > std::numeric_limits<std::uint32_t>::max()) {
      c.fail("grid origin or dimensions are malformed");
    }
    g.grid.origin[axis] = origin[axis].get<double>();
    g.grid.dims[axis] = dims[axis].get<std::uint32_t>();
  }
  g.grid.cell_size = number_field<double>(c, "/grid/cell_size");
  const auto cells = BackgroundGrid::checked_cell_count(g.grid.dims);
  if (!cells) c.fail("grid dimensions overflow");
  const std::vector<std::uint32_t> counts = c.get_counts("cell_counts", *cells);
  g.grid.cell_offsets.assign(counts.size() + 1, 0);
  std::uint64_t references = 0;
  for (std::size_t cell = 0; cell < counts.size(); ++cell) {
    references += counts[cell];
    if (references > std::numeric_limits<std::uint32_t>::max()) {
      c.fail("grid has 2^32 or more references");
    }
    g.grid.cell_offsets[cell + 1] = static_cast<std::uint32_t>(references);
  }
  g.grid.cell_triangles =
      c.get<std::uint32_t, Buffer<std::uint32_t>>("cell_triangles", c.count("/grid/references"));
  g.grid.validate(*g.surface, c.source());
  return g;
}

}  // namespace ncv
