// Grid files (kind GRID) as `distance` reads them: Container::parse, load_indexed_reference
// (mesh, hash, topology, grid validation), then what `distance` does with an accepted
// grid: signed distances of points on, around and inside the nominal by the grid search,
// which must neither crash nor hang whatever cell lists the file holds. (Its results are
// not compared with brute force here: sealing lets the fuzzer forge cell lists that miss
// cells, which validation documents it cannot tell; fuzz_mesh checks the grids ncverify
// builds itself bit for bit.)
#include "distance/signed_distance.hpp"
#include "files/container.hpp"
#include "files/grid_file.hpp"
#include "fuzz_support.hpp"

namespace {

// The nominal's vertices, its bounding-box corners pushed out by half a diagonal and its
// centre: points on, outside and inside the part. Capped so one execution stays fast.
std::vector<ncv::Vec3> query_points(const ncv::Mesh& mesh) {
  std::vector<ncv::Vec3> points;
  for (std::size_t v = 0; v < mesh.vertex_count() && v < 64; ++v)
    points.push_back(mesh.vertices[v]);
  const ncv::BoundingBox box = ncv::bounding_box(mesh);
  const ncv::Vec3 centre = box.center();
  const ncv::Vec3 reach = box.max - centre + 0.5 * box.diagonal() * ncv::Vec3{1, 1, 1};
  for (int corner = 0; corner < 8; ++corner) {
    points.push_back(centre + ncv::Vec3{(corner & 1 ? 1 : -1) * reach[0],
                                        (corner & 2 ? 1 : -1) * reach[1],
                                        (corner & 4 ? 1 : -1) * reach[2]});
  }
  points.push_back(centre);
  return points;
}

void read_grid(ncv::Buffer<char> bytes) {
  const ncv::Container c = ncv::Container::parse(std::move(bytes), "fuzz.grid", ncv::FileKind::grid,
                                                 ncv::kGridFormatVersion);
  const ncv::IndexedReference g = ncv::load_indexed_reference(c);
  const std::vector<ncv::Vec3> points = query_points(*g.mesh);
  const ncv::SignMethod sign = g.surface->automatic_sign_method();
  const ncv::SearchIndex search(g);
  const ncv::DistanceField field = ncv::compute_signed_distances(search, points, {}, sign);
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (field.closest_face[i] >= g.mesh->triangle_count()) __builtin_trap();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ncv::fuzz::quiet_and_serial();
  ncv::fuzz::accepts([&] { read_grid(ncv::Buffer<char>(data, data + size)); });
  ncv::fuzz::accepts([&] { read_grid(ncv::fuzz::sealed_container(data, size)); });
  return 0;
}
