#include "runners/verify_runner.hpp"

#include <spdlog/spdlog.h>

#include <array>
#include <filesystem>
#include <memory>

#include <tbb/parallel_invoke.h>

#include "files/distance_file.hpp"
#include "files/grid_file.hpp"
#include "files/samples_file.hpp"
#include "mesh/mesh_reader.hpp"
#include "runners/phase_log.hpp"
#include "runners/run_folder.hpp"
#include "util/buffer.hpp"
#include "util/error.hpp"
#include "util/input_bytes.hpp"
#include "util/output_file.hpp"

namespace ncv {
namespace {

namespace fs = std::filesystem;

std::string stem(const std::string& path) {
  return path == "-" ? "stdin" : fs::path(path).stem().string();
}

fs::path folder_path(const RunJob& job) {
  return job.folder.empty() ? fs::path(stem(job.workpiece) + ".ncverify") : fs::path(job.folder);
}

// A path the user gave, else the default in the output folder.
fs::path in_folder(const std::string& given, const fs::path& otherwise) {
  return given.empty() ? otherwise : fs::path(given);
}

// Where one direction's intermediate files go.
struct DirectionFiles {
  fs::path samples, grid, distances;
};

std::string phase_name(Direction direction, const std::string& step) {
  return direction == Direction::forward ? step : "reverse " + step;
}

// run's hooks: each step logged and timed, and with `files` (by direction, forward first)
// its intermediate file written as soon as it is done; each distance file names the samples
// file written before it.
StepHooks logging_and_writing(const std::optional<std::array<DirectionFiles, 2>>& files,
                              RunFolder& folder, PhaseLog& phases) {
  struct Written {
    std::uint64_t samples_hash[2] = {0, 0};
  };
  auto written = std::make_shared<Written>();
  const auto in = [files](Direction direction) -> const DirectionFiles& {
    return (*files)[static_cast<std::size_t>(direction)];
  };
  StepHooks hooks;
  hooks.sampled = [&phases, &folder, in, files, written](const SampledSurface& sampled,
                                                         Direction direction) {
    log_sampling(sampled);
    phases.done(phase_name(direction, "sample"));
    if (!files) return;
    phases.time("write", [&] {
      folder.write(in(direction).samples, OutputKind::binary, [&](OutputFile& out) {
        written->samples_hash[static_cast<std::size_t>(direction)] =
            write_samples_file(sampled.samples, out);
      });
    });
  };
  hooks.indexed = [&phases, &folder, in, files](const IndexedSurface& indexed,
                                                Direction direction) {
    log_grid(indexed);
    phases.done(phase_name(direction, "grid-build"));
    if (!files) return;
    phases.time("write", [&] {
      folder.write(in(direction).grid, OutputKind::binary, [&](OutputFile& out) {
        write_grid_file(indexed.reference, indexed.statistics, out);
      });
    });
  };
  hooks.measured = [&phases, &folder, in, files, written](const DistanceSet& distances,
                                                          double seconds) {
    log_distances(distances, seconds);
    phases.done(phase_name(distances.direction, "distance"), seconds,
                phase_name(distances.direction, "certify"));
    if (!files) return;
    const DirectionFiles& to = in(distances.direction);
    const std::uint64_t hash = written->samples_hash[static_cast<std::size_t>(distances.direction)];
    phases.time("write", [&] {
      folder.write(to.distances, OutputKind::binary, [&](OutputFile& out) {
        write_distance_file(distances,
                            link_samples(to.samples.string(), hash, to.distances.string()), out);
      });
    });
  };
  return hooks;
}

// One direction's steps: sample, index the reference, measure.
DistanceSet measure_direction(Mesh sampled_mesh, const std::string& sampled_source,
                              std::shared_ptr<const Mesh> reference_mesh,
                              const std::string& reference_source, const SampleOptions& sampling,
                              const VerifyOptions& options, Direction direction,
                              const StepHooks& hooks) {
  SampledSurface sampled = sample_surface(std::move(sampled_mesh), sampled_source, sampling);
  if (hooks.sampled) hooks.sampled(sampled, direction);
  // The reverse direction's reference, the workpiece, on the arrays (reference_surface.hpp).
  const IndexedSurface indexed =
      index_surface(std::move(reference_mesh), reference_source, options.grid,
                    direction == Direction::reverse ? SurfaceHolding::arrays
                                                    : SurfaceHolding::halfedges_where_possible);
  // The search's boxes belong to the index, as the grid does (timed with it).
  const SearchIndex search(indexed.reference);
  if (hooks.indexed) hooks.indexed(indexed, direction);
  DistanceOptions distance = options.distance;
  distance.direction = direction;

  double seconds = 0;
  DistanceSet distances = measure_distances(std::move(sampled.samples), search, distance, &seconds);
  if (hooks.measured) hooks.measured(distances, seconds);
  return distances;
}

// The nominal is sampled with the workpiece's absolute step and scheme, so both directions
// measure at the same density.
SampleOptions reverse_sampling(const SampleSet& forward, const SampleOptions& options) {
  SampleOptions reverse = options;
  reverse.step = SamplingStep{forward.step, false};
  reverse.step_label = forward.step_spec + " of " + fs::path(forward.source).filename().string();
  return reverse;
}

}  // namespace

Measurements measure_part(Mesh workpiece, const std::string& workpiece_source, Mesh nominal,
                          const std::string& nominal_source, const VerifyOptions& options,
                          const StepHooks& hooks) {
  Measurements measured;
  // The nominal (small) is copied for the reverse direction's samples; the workpiece is not:
  // the reverse direction measures against the forward samples' own (which outlive it).
  Mesh nominal_to_sample = options.two_sided ? nominal : Mesh{};
  measured.forward = measure_direction(
      std::move(workpiece), workpiece_source, std::make_shared<const Mesh>(std::move(nominal)),
      nominal_source, options.sampling, options, Direction::forward, hooks);
  if (options.two_sided) {
    const Mesh& sampled_workpiece = measured.forward.samples.mesh;
    measured.reverse = measure_direction(
        std::move(nominal_to_sample), nominal_source,
        std::shared_ptr<const Mesh>(std::shared_ptr<const Mesh>{}, &sampled_workpiece),
        workpiece_source, reverse_sampling(measured.forward.samples, options.sampling), options,
        Direction::reverse, hooks);
  }
  return measured;
}

// What the kept freed buffers may still hold once the measuring is done.
constexpr std::size_t kPictureBuffers = std::size_t{64} << 20;

ColorizeOptions colorize_options(const VerifyOptions& options) {
  ColorizeOptions colorize = options.colorize;
  colorize.tolerance = options.report.tolerance;
  colorize.units = options.report.units;
  return colorize;
}

ReportOptions report_options(const VerifyOptions& options) {
  ReportOptions report = options.report;
  report.one_sided = report.one_sided || !options.two_sided;
  return report;
}

// The paths the user gave for run's optional outputs, checked before any work.
void check_given_outputs(const RunJob& job) {
  for (const std::string& path : {job.histogram_svg, job.legend_svg, job.timings}) {
    check_writable(path);
  }
}

int run_verification(const RunJob& job) {
  const std::string part = stem(job.workpiece);
  const bool keep_all = job.keep == Keep::all, keep_reports = job.keep != Keep::none;
  const VerifyOptions& options = job.options;
  const std::string workpiece_source = input_name(job.workpiece);
  const std::string nominal_source = input_name(job.nominal);
  PhaseLog phases;

  // Inputs and output paths first: a run refused for either creates nothing.
  Mesh workpiece = read_mesh(job.workpiece);
  Mesh nominal = read_mesh(job.nominal);
  check_parts(workpiece, workpiece_source, nominal, nominal_source);
  check_given_outputs(job);
  RunFolder folder(keep_reports ? folder_path(job) : fs::path("."));
  folder.create();
  phases.done("read");

  // The nominal's grid file keeps the nominal's name, as grid-build names it.
  std::optional<std::array<DirectionFiles, 2>> files;
  if (keep_all) {
    files = {{{folder / (part + ".samples"), folder / (stem(job.nominal) + ".grid"),
               folder / (part + ".dist")},
              {folder / (part + ".reverse.samples"), folder / (part + ".reverse.grid"),
               folder / (part + ".reverse.dist")}}};
  }
  const Measurements measured =
      measure_part(std::move(workpiece), workpiece_source, std::move(nominal), nominal_source,
                   options, logging_and_writing(files, folder, phases));
  const DistanceSet& forward = measured.forward;
  const std::optional<DistanceSet>& reverse = measured.reverse;
  // The statistics' large buffers (the percentiles' brackets, the rank selection's buckets)
  // take the kept ones, whose pages are backed already: released before them, they were
  // cleared afresh (stats at 1.8 M samples 0.160 -> 0.117 s, docs/PERFORMANCE.md). Then the
  // large buffers are made: kept ones would stay resident under the reports' and pictures'
  // allocations and raise the peak (by 16 MB on the two-sided finishing job). The pictures'
  // buffers (the lattice read for each PLY, the page's mesh: 10 MB each on that job) take
  // some of the smaller ones.
  VerificationReport report =
      make_verification_report(forward, reverse ? &*reverse : nullptr, report_options(options));
  release_kept_buffers(kPictureBuffers);
  report.trace = traceability(job.command_line);
  if (keep_reports) {
    folder.write(folder / (part + ".report.txt"), OutputKind::text,
                 [&](OutputFile& out) { out.write(format_report(report, ReportFormat::text)); });
    folder.write(folder / (part + ".report.json"), OutputKind::text,
                 [&](OutputFile& out) { out.write(format_report(report, ReportFormat::json)); });
  }
  const auto report_files = [&](const std::string& prefix, const std::string& histogram) {
    if (!keep_reports) return ReportFiles{histogram, "", ""};
    return ReportFiles{histogram, (folder / (prefix + ".regions.csv")).string(),
                       (folder / (prefix + ".histogram.csv")).string()};
  };
  const auto write_extras = [&](const PartReport& direction, const ReportFiles& paths) {
    for (OutputFile& out : write_report_files(direction, paths)) {
      out.commit();
      folder.written(out.path());
    }
  };
  const std::string histogram =
      keep_reports ? in_folder(job.histogram_svg, folder / (part + ".histogram.svg")).string()
                   : job.histogram_svg;
  write_extras(report.main, report_files(part, histogram));
  if (keep_reports && report.reverse) {
    const std::string prefix = part + ".reverse";
    write_extras(*report.reverse,
                 report_files(prefix, (folder / (prefix + ".histogram.svg")).string()));
  }
  phases.done("stats");

  if (keep_reports) {
    const ColorizeOptions colorize = colorize_options(options);
    const auto paint = [&](const DistanceSet& distances, const std::string& prefix,
                           const fs::path& legend, std::span<const std::uint32_t> regions) {
      const fs::path ply = folder / (prefix + ".ply");
      write_colored(distances, colorize, ply.string(), legend.string(), regions);
      folder.written(ply);
      folder.written(legend);
    };
    // The two coloured PLYs and the HTML page read only the report and the distances, and
    // each is mostly one thread's work (bytes in order): side by side they took 0.30-0.33 s
    // of the two-sided finishing job on 2 threads against 0.49 s one after the other
    // (docs/PERFORMANCE.md). One phase, "colorize", times all three.
    tbb::parallel_invoke(
        [&] {
          paint(forward, part, in_folder(job.legend_svg, folder / (part + ".legend.svg")),
                report.main.sample_region);
        },
        [&] {
          if (!reverse) return;
          paint(*reverse, part + ".reverse", folder / (part + ".reverse.legend.svg"),
                report.reverse->sample_region);
        },
        [&] {
          folder.write(folder / (part + ".report.html"), OutputKind::text,
                       [&](OutputFile& out) { out.write(html_page(report, colorize)); });
        });
    phases.done("colorize");
  }

  OutputFile out("-", OutputKind::text);
  out.write(format_report(report, job.format));
  out.commit();
  nlohmann::json figures = {{"triangles", forward.samples.mesh.triangle_count()},
                            {"samples", forward.samples.sample_count()},
                            {"nominal_triangles", forward.reference.triangles},
                            {"triangles_tested_per_sample", forward.triangles_tested_per_sample()}};
  if (reverse) {
    figures["reverse_samples"] = reverse->samples.sample_count();
    figures["reverse_triangles_tested_per_sample"] = reverse->triangles_tested_per_sample();
  }
  phases.summary(job.timings, figures);
  folder.keep();
  if (keep_reports) spdlog::info("outputs in {}/", folder.path().string());
  return verdict_status(report);
}

}  // namespace ncv
