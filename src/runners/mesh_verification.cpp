#include "runners/mesh_verification.hpp"

#include "render/colored_tri_mesh.hpp"
#include "util/error.hpp"

namespace ncv {
namespace {

TriMesh colored(const DistanceSet& distances, const ColorizeOptions& options) {
  const ColoredSurface surface = colorize(distances, options);
  return colored_tri_mesh(surface.mesh, surface.map);
}

}  // namespace

Verification verify(const TriMesh& workpiece, const TriMesh& nominal, const VerifyOptions& options,
                    const MeshNames& names) {
  Mesh workpiece_arrays = mesh_arrays(workpiece, names.workpiece);
  Mesh nominal_arrays = mesh_arrays(nominal, names.nominal);
  check_parts(workpiece_arrays, names.workpiece, nominal_arrays, names.nominal);
  Measurements measured = measure_part(std::move(workpiece_arrays), names.workpiece,
                                       std::move(nominal_arrays), names.nominal, options);
  Verification verification;
  verification.forward = std::make_unique<const DistanceSet>(std::move(measured.forward));
  if (measured.reverse) {
    verification.reverse = std::make_unique<const DistanceSet>(std::move(*measured.reverse));
  }
  verification.report = make_verification_report(*verification.forward, verification.reverse.get(),
                                                 report_options(options));
  verification.colorize = colorize_options(options);
  return verification;
}

TriMesh colored_workpiece(const Verification& verification) {
  return colored(*verification.forward, verification.colorize);
}

TriMesh colored_nominal(const Verification& verification) {
  if (!verification.reverse) {
    throw UsageError("the nominal is coloured by the reverse direction: verify two-sided");
  }
  return colored(*verification.reverse, verification.colorize);
}

}  // namespace ncv
