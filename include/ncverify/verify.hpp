// ncverify as a library for OpenMesh users (README.md "The library"): verifies a machined
// workpiece against its nominal part in process, both given as OpenMesh triangle meshes in
// double precision, with the options and the results of `ncverify run` and no file written.
//
//   #include <ncverify/verify.hpp>
//
//   ncv::TriMesh workpiece, nominal;             // OpenMesh::TriMesh_ArrayKernelT, Vec3d points
//   OpenMesh::IO::read_mesh(workpiece, "part.stl");
//   OpenMesh::IO::read_mesh(nominal, "nominal.stl");
//   ncv::VerifyOptions options;                  // run's defaults: step 0.1 %, scheme all, ...
//   options.report.tolerance = ncv::Tolerance{-0.05, 0.1};
//   const ncv::Verification result = ncv::verify(workpiece, nominal, options);
//   result.report.main.statistics.max.value;     // d_max and every other measure of `run`
//   result.report.reverse->statistics.max.value; // the nominal's side (both directions)
//   ncv::format_report(result.report, ncv::ReportFormat::json);  // run's report, to the bit
//   ncv::TriMesh colored = ncv::colored_workpiece(result);       // colours + "signed_error"
//   ncv::TriMesh nominal_colored = ncv::colored_nominal(result);
//
// The option and result types are ncverify's own (runners/verify_runner.hpp,
// files/distance_file.hpp, statistics/statistics_report.hpp); errors are thrown as
// ncv::InputError and ncv::UsageError (util/error.hpp). Work runs on oneTBB's threads
// (limit them with tbb::global_control); results do not depend on their number. Warnings
// go to spdlog's default logger: ncv::setup_logging (util/logging.hpp) sends them to
// standard error as the command does.
#pragma once

#include "mesh/tri_mesh.hpp"
#include "render/colored_tri_mesh.hpp"
#include "runners/mesh_verification.hpp"
#include "statistics/statistics_report.hpp"
#include "util/error.hpp"
#include "util/logging.hpp"
