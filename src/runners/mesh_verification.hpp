// Verification in process, the library's entry (include/ncverify/verify.hpp): a workpiece
// and a nominal OpenMesh TriMesh through the steps of `ncverify run` (measure_part, then the
// report), with run's options and run's results to the bit, and nothing written.
#pragma once

#include <memory>
#include <string>

#include "mesh/tri_mesh.hpp"
#include "runners/verify_runner.hpp"

namespace ncv {

// How the meshes are named in the results and reports, where `run` names them by their
// paths: the report's `part` is the workpiece name's stem.
struct MeshNames {
  std::string workpiece = "workpiece";
  std::string nominal = "nominal";
};

// The directions' results are held by pointer, so that `report`, which points into them,
// stays valid when the Verification moves.
struct Verification {
  // Per sample of the workpiece: its position, triangle and lattice point, signed error,
  // closest nominal point and face.
  std::unique_ptr<const DistanceSet> forward;
  // The same per sample of the nominal, measured against the workpiece; null one-sided.
  std::unique_ptr<const DistanceSet> reverse;
  VerificationReport report;  // statistics, verdict and out-of-tolerance regions of each
  ColorizeOptions colorize;   // how run paints: its colour options, the report's zone
};

// Throws InputError (naming the mesh) for a mesh a file reader would refuse or with deleted
// elements not collected, or for parts too far apart to belong together; UsageError for
// options `run` refuses.
Verification verify(const TriMesh& workpiece, const TriMesh& nominal,
                    const VerifyOptions& options = {}, const MeshNames& names = {});

// The workpiece, or (two-sided) the nominal, as run's PLYs paint them
// (colorize_runner.hpp): per-vertex colours and the signed error as the vertex property
// kSignedErrorProperty (render/colored_tri_mesh.hpp). colored_nominal throws UsageError for
// a one-sided verification.
TriMesh colored_workpiece(const Verification& verification);
TriMesh colored_nominal(const Verification& verification);

}  // namespace ncv
