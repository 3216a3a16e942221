#include "runners/verify_runner.hpp"

#include <spdlog/spdlog.h>

#include <filesystem>

#include "files/distance_file.hpp"
#include "files/grid_file.hpp"
#include "files/samples_file.hpp"
#include "mesh/mesh_reader.hpp"
#include "runners/phase_log.hpp"
#include "util/error.hpp"
#include "util/input_bytes.hpp"
#include "util/output_file.hpp"

namespace ncv {
namespace {

namespace fs = std::filesystem;

std::string stem(const std::string& path) {
  return path == "-" ? "stdin" : fs::path(path).stem().string();
}

template <class Write>
void write_file(const fs::path& path, OutputKind kind, Write&& write) {
  OutputFile out(path.string(), kind);
  write(out);
  out.commit();
}

fs::path output_folder(const RunJob& job) {
  const fs::path folder =
      job.folder.empty() ? fs::path(stem(job.workpiece) + ".ncverify") : fs::path(job.folder);
  std::error_code error;
  fs::create_directories(folder, error);
  if (error) {
    throw InputError(folder.string(), "cannot create the output folder: " + error.message());
  }
  return folder;
}

// A path the user gave, else the default in the output folder.
fs::path in_folder(const std::string& given, const fs::path& otherwise) {
  return given.empty() ? otherwise : fs::path(given);
}

}  // namespace

int run_verification(const RunJob& job) {
  const std::string part = stem(job.workpiece);
  const fs::path folder = output_folder(job);
  const VerifyOptions& options = job.options;
  PhaseLog phases;

  Mesh workpiece = read_mesh(job.workpiece);
  Mesh nominal = read_mesh(job.nominal);
  refuse_if_apart(bounding_box(workpiece), input_name(job.workpiece), bounding_box(nominal),
                  input_name(job.nominal));
  phases.done("read");

  SampledSurface sampled =
      sample_surface(std::move(workpiece), input_name(job.workpiece), options.sampling);
  log_sampling(sampled);
  phases.done("sample");
  phases.time("write", [&] {
    write_file(folder / (part + ".samples"), OutputKind::binary,
               [&](OutputFile& out) { write_samples_file(sampled.samples, out); });
  });

  const IndexedSurface indexed =
      index_surface(std::move(nominal), input_name(job.nominal), options.grid);
  phases.done("grid-build");
  phases.time("write", [&] {
    write_file(folder / (stem(job.nominal) + ".grid"), OutputKind::binary, [&](OutputFile& out) {
      write_grid_file(indexed.reference, indexed.statistics, out);
    });
  });

  double distance_seconds = 0;
  const DistanceSet distances = measure_distances(std::move(sampled.samples), indexed.reference,
                                                  options.distance, &distance_seconds);
  log_distances(distances, distance_seconds);
  phases.done("distance");
  phases.time("write", [&] {
    write_file(folder / (part + ".dist"), OutputKind::binary,
               [&](OutputFile& out) { write_distance_file(distances, out); });
  });

  const PartReport report = make_report(distances, options.report);
  write_file(folder / (part + ".report.txt"), OutputKind::text,
             [&](OutputFile& out) { out.write(format_report(report, ReportFormat::text)); });
  write_file(folder / (part + ".report.json"), OutputKind::text,
             [&](OutputFile& out) { out.write(format_report(report, ReportFormat::json)); });
  write_file(in_folder(job.histogram_svg, folder / (part + ".histogram.svg")), OutputKind::text,
             [&](OutputFile& out) { out.write(histogram_svg(report)); });
  phases.done("stats");

  ColorizeOptions colorize = options.colorize;
  colorize.tolerance = options.report.tolerance;
  write_colored(distances, colorize, (folder / (part + ".ply")).string(),
                in_folder(job.legend_svg, folder / (part + ".legend.svg")).string());
  phases.done("colorize");

  OutputFile out("-", OutputKind::text);
  out.write(format_report(report, job.format));
  out.commit();
  phases.summary(job.timings,
                 {{"triangles", distances.samples.mesh.triangle_count()},
                  {"samples", distances.samples.sample_count()},
                  {"nominal_triangles", distances.reference.triangles},
                  {"triangles_tested_per_sample", distances.triangles_tested_per_sample}});
  spdlog::info("outputs in {}/", folder.string());
  return verdict_status(report);
}

}  // namespace ncv
