// Verification in process, the library's entry (include/ncverify/verify.hpp): a workpiece
// and a nominal OpenMesh TriMesh through the steps of `ncverify run` (sample, grid,
// distance, report), with run's options and run's results to the bit, and nothing written.
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

struct Verification {
  // Per sample of the workpiece: its position, triangle and lattice point, signed error,
  // closest nominal point and face. Held by pointer, so that `report`, which points into
  // it, stays valid when the Verification moves.
  std::unique_ptr<const DistanceSet> forward;
  PartReport report;         // the statistics, the verdict and the out-of-tolerance regions
  ColorizeOptions colorize;  // how run paints the workpiece: its options, the report's zone
};

// Throws InputError (naming the mesh) for a mesh a file reader would refuse or with deleted
// elements not collected, or for parts too far apart to belong together; UsageError for
// options `run` refuses.
Verification verify(const TriMesh& workpiece, const TriMesh& nominal,
                    const VerifyOptions& options = {}, const MeshNames& names = {});

// The workpiece as run's PLY paints it (colorize_runner.hpp), with per-vertex colours and
// the signed error as the vertex property kSignedErrorProperty (render/colored_tri_mesh.hpp).
TriMesh colored_workpiece(const Verification& verification);

}  // namespace ncv
