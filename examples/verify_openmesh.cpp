// An OpenMesh program that verifies a machined part with ncverify's library:
//
//   verify_openmesh WORKPIECE NOMINAL TOLERANCE OUT
//
// reads both meshes with OpenMesh's own reader, verifies the workpiece against the nominal
// in process with `ncverify run --coarse`'s defaults (both directions) and the tolerance zone (e.g.
// -0.05:0.1), prints run's JSON report on standard output, writes the coloured workpiece
// OUT.ply and the coloured nominal OUT.reverse.ply with OpenMesh's PLY writer (vertex colours
// and the signed error as the property "signed_error") and names each one's worst vertex on
// standard error. Exit status as run's: 0 within tolerance, 1 out of it, 2 bad input.
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

// With its vertex colours and (Custom) the persistent error property.
void write_colored(const ncv::TriMesh& colored, const std::string& path) {
  const OpenMesh::IO::Options what = OpenMesh::IO::Options::Binary |
                                     OpenMesh::IO::Options::VertexColor |
                                     OpenMesh::IO::Options::Custom;
  if (!OpenMesh::IO::write_mesh(colored, path, what)) {
    throw ncv::InputError(path, "OpenMesh cannot write it");
  }
}

// The vertex with the largest |signed error|, read back from the property by its name.
void name_worst_vertex(ncv::TriMesh& colored, const std::string& name) {
  const auto error = OpenMesh::VProp<double>(colored, ncv::kSignedErrorProperty);
  ncv::TriMesh::VertexHandle worst;
  for (const auto vertex : colored.vertices()) {
    if (std::isnan(error[vertex])) continue;
    if (!worst.is_valid() || std::abs(error[vertex]) > std::abs(error[worst])) worst = vertex;
  }
  if (!worst.is_valid()) return;
  const ncv::TriMesh::Point p = colored.point(worst);
  const ncv::TriMesh::Color c = colored.color(worst);
  std::fprintf(stderr, "%s: worst vertex %d at (%g, %g, %g): error %g, colour #%02x%02x%02x\n",
               name.c_str(), worst.idx(), p[0], p[1], p[2], error[worst], c[0], c[1], c[2]);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: %s WORKPIECE NOMINAL TOLERANCE OUT\n", argv[0]);
    return 2;
  }
  ncv::setup_logging(ncv::Verbosity::normal);  // warnings on stderr, as the command has them
  try {
    const ncv::TriMesh workpiece = read_tri_mesh(argv[1]);
    const ncv::TriMesh nominal = read_tri_mesh(argv[2]);
    ncv::VerifyOptions options;
    options.report.tolerance = ncv::parse_tolerance(argv[3]);
    options.colorize.coarse = true;  // colour the meshes' own vertices (run --coarse)

    // Named by their paths, as `ncverify run` names them, so the reports read alike.
    const ncv::Verification result = ncv::verify(workpiece, nominal, options, {argv[1], argv[2]});
    std::fputs(ncv::format_report(result.report, ncv::ReportFormat::json).c_str(), stdout);

    const std::string out = argv[4];
    ncv::TriMesh workpiece_colored = ncv::colored_workpiece(result);
    write_colored(workpiece_colored, out + ".ply");
    name_worst_vertex(workpiece_colored, "workpiece");
    ncv::TriMesh nominal_colored = ncv::colored_nominal(result);
    write_colored(nominal_colored, out + ".reverse.ply");
    name_worst_vertex(nominal_colored, "nominal");
    return ncv::verdict_status(result.report);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "verify_openmesh: %s\n", e.what());
    return 2;
  }
}
