// Mesh files as `sample`, `grid-build` and `run` read them: parse_mesh detects the format
// from the content (binary or ASCII STL parsed by ncverify, PLY, OBJ and OFF through
// OpenMesh). An accepted mesh must keep parse_mesh's promise (triangles, every index in
// range, finite coordinates); a small one then goes through what the commands do next:
// the sample-count estimate and the lattice (as `sample --step 5%`), the nominal's
// topology, orientation and grid (as `grid-build`), and the signed distances of the
// samples, where the grid search must agree bit for bit with brute force.
#include <cmath>
#include <utility>

#include "distance/signed_distance.hpp"
#include "files/grid_file.hpp"
#include "fuzz_support.hpp"
#include "mesh/mesh_reader.hpp"
#include "sampling/sampling.hpp"

namespace {

constexpr std::size_t kMaxTrianglesDownstream = 64;
constexpr std::uint64_t kMaxSamples = 4096;

void check_promise(const ncv::Mesh& mesh) {
  if (mesh.triangles.empty()) __builtin_trap();
  for (const ncv::Triangle& t : mesh.triangles) {
    for (std::uint32_t v : t) {
      if (v >= mesh.vertex_count()) __builtin_trap();
    }
  }
  for (const ncv::Vec3& p : mesh.vertices) {
    if (!ncv::is_finite(p)) __builtin_trap();
  }
}

void verify(const ncv::Mesh& workpiece) {
  // `sample` resolves a relative step on the bounding-box diagonal and refuses a mesh
  // without extent, then refuses sample counts beyond its memory budget.
  const double step = 0.05 * ncv::bounding_box(workpiece).diagonal();
  if (!(step > 0) || !std::isfinite(step)) return;
  ncv::SamplingPlan plan = ncv::plan_sampling(workpiece, step, ncv::SamplingScheme::all);
  if (ncv::predicted_sample_count(workpiece, plan) > kMaxSamples) return;
  const ncv::SampleSet samples = ncv::sample_mesh(workpiece, std::move(plan));

  const ncv::IndexedReference g = ncv::index_reference(workpiece, "fuzz", {}, nullptr);
  const ncv::SignMethod sign = g.surface->automatic_sign_method();
  const ncv::SearchIndex search(g);
  const ncv::DistanceField by_grid =
      ncv::compute_signed_distances(search, samples.positions, {}, sign);
  const ncv::DistanceField by_brute_force =
      ncv::compute_signed_distances(*g.surface, samples.positions, {}, sign);
  for (std::size_t i = 0; i < samples.sample_count(); ++i) {
    if (by_grid.closest_face[i] != by_brute_force.closest_face[i] ||
        std::memcmp(&by_grid.distance[i], &by_brute_force.distance[i], sizeof(double)) != 0) {
      __builtin_trap();
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ncv::fuzz::quiet_and_serial();
  ncv::fuzz::accepts([&] {
    const ncv::Mesh mesh =
        ncv::parse_mesh({reinterpret_cast<const char*>(data), size}, "fuzz.mesh");
    check_promise(mesh);
    if (mesh.triangle_count() <= kMaxTrianglesDownstream) verify(mesh);
  });
  return 0;
}
