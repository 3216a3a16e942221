#include "runners/mesh_verification.hpp"

#include "render/colored_tri_mesh.hpp"

namespace ncv {

Verification verify(const TriMesh& workpiece, const TriMesh& nominal, const VerifyOptions& options,
                    const MeshNames& names) {
  Mesh workpiece_arrays = mesh_arrays(workpiece, names.workpiece);
  Mesh nominal_arrays = mesh_arrays(nominal, names.nominal);
  refuse_if_apart(bounding_box(workpiece_arrays), names.workpiece, bounding_box(nominal_arrays),
                  names.nominal);
  SampledSurface sampled =
      sample_surface(std::move(workpiece_arrays), names.workpiece, options.sampling);
  const IndexedSurface indexed =
      index_surface(std::move(nominal_arrays), names.nominal, options.grid);

  Verification verification;
  verification.forward = std::make_unique<const DistanceSet>(
      measure_distances(std::move(sampled.samples), indexed.reference, options.distance));
  verification.report = make_report(*verification.forward, options.report);
  verification.colorize = options.colorize;
  verification.colorize.tolerance = options.report.tolerance;
  return verification;
}

TriMesh colored_workpiece(const Verification& verification) {
  const ColoredSurface colored = colorize(*verification.forward, verification.colorize);
  return colored_tri_mesh(colored.mesh, colored.map);
}

}  // namespace ncv
