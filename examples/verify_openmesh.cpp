// An OpenMesh program that verifies a machined part with ncverify's library:
//
//   verify_openmesh WORKPIECE NOMINAL TOLERANCE COLORED.ply
//
// reads both meshes with OpenMesh's own reader, verifies the workpiece against the nominal
// in process with `ncverify run`'s defaults and the tolerance zone (e.g. -0.05:0.1), prints
// run's JSON report on standard output, writes the coloured workpiece with OpenMesh's PLY
// writer (vertex colours and the signed error as the property "signed_error") and names
// the worst vertex on standard error. Exit status as run's: 0 within tolerance, 1 out of it,
// 2 bad input.
#include <OpenMesh/Core/IO/MeshIO.hh>  // before any mesh type, as OpenMesh asks
#include <OpenMesh/Core/Utils/PropertyManager.hh>

#include <cmath>
#include <cstdio>
#include <exception>
#include <ncverify/verify.hpp>
#include <string>

namespace {

ncv::TriMesh read_tri_mesh(const std::string& path) {
  ncv::TriMesh mesh;
  if (!OpenMesh::IO::read_mesh(mesh, path)) throw ncv::InputError(path, "OpenMesh cannot read it");
  return mesh;
}

// The vertex with the largest |signed error|, read back from the property OpenMesh users
// find by name.
void report_worst_vertex(ncv::TriMesh& colored) {
  const auto error = OpenMesh::VProp<double>(colored, ncv::kSignedErrorProperty);
  ncv::TriMesh::VertexHandle worst;
  for (const auto vertex : colored.vertices()) {
    if (std::isnan(error[vertex])) continue;
    if (!worst.is_valid() || std::abs(error[vertex]) > std::abs(error[worst])) worst = vertex;
  }
  if (!worst.is_valid()) return;
  const ncv::TriMesh::Point p = colored.point(worst);
  const ncv::TriMesh::Color c = colored.color(worst);
  std::fprintf(stderr, "worst vertex %d at (%g, %g, %g): error %g, colour #%02x%02x%02x\n",
               worst.idx(), p[0], p[1], p[2], error[worst], c[0], c[1], c[2]);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: %s WORKPIECE NOMINAL TOLERANCE COLORED.ply\n", argv[0]);
    return 2;
  }
  ncv::setup_logging(ncv::Verbosity::normal);  // warnings on stderr, as the command has them
  try {
    const ncv::TriMesh workpiece = read_tri_mesh(argv[1]);
    const ncv::TriMesh nominal = read_tri_mesh(argv[2]);
    ncv::VerifyOptions options;
    options.report.tolerance = ncv::parse_tolerance(argv[3]);

    // Named by their paths, as `ncverify run` names them, so the reports read alike.
    const ncv::Verification result = ncv::verify(workpiece, nominal, options, {argv[1], argv[2]});
    std::fputs(ncv::format_report(result.report, ncv::ReportFormat::json).c_str(), stdout);

    ncv::TriMesh colored = ncv::colored_workpiece(result);
    const OpenMesh::IO::Options what = OpenMesh::IO::Options::Binary |
                                       OpenMesh::IO::Options::VertexColor |
                                       OpenMesh::IO::Options::Custom;
    if (!OpenMesh::IO::write_mesh(colored, argv[4], what)) {
      throw ncv::InputError(argv[4], "OpenMesh cannot write it");
    }
    report_worst_vertex(colored);
    return ncv::verdict_status(result.report);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "verify_openmesh: %s\n", e.what());
    return 2;
  }
}
