#include "runners/colorize_runner.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "files/distance_job.hpp"
#include "render/ply_writer.hpp"
#include "render/svg_legend.hpp"
#include "statistics/error_regions.hpp"
#include "statistics/readable_numbers.hpp"
#include "util/error.hpp"
#include "util/output_file.hpp"

namespace ncv {
namespace {

// Without a range: for the tolerance map the data's extent (at least the zone), so the
// deepest shade marks the worst point; for the continuous maps ±max|d|, so zero is the
// neutral colour.
ValueRange default_range(const DistanceSet& distances, ColorMapKind kind,
                         const std::optional<Tolerance>& tolerance) {
  const auto [lo, hi] =
      std::minmax_element(distances.field.distance.begin(), distances.field.distance.end());
  if (kind == ColorMapKind::tolerance) {
    return {std::min(*lo, tolerance->lower), std::max(*hi, tolerance->upper)};
  }
  const double reach = std::max({std::abs(*lo), std::abs(*hi), 1e-12});
  return {-reach, reach};
}

}  // namespace

ColorMap choose_color_map(const DistanceSet& distances, const ColorizeOptions& options) {
  const ColorMapKind kind =
      options.map.value_or(options.tolerance ? ColorMapKind::tolerance : ColorMapKind::diverging);
  if (kind == ColorMapKind::tolerance && !options.tolerance) {
    throw UsageError("the tolerance colour map needs a tolerance: give --tol");
  }
  const ValueRange range =
      options.range.value_or(default_range(distances, kind, options.tolerance));
  return make_color_map(kind, range, options.tolerance);
}

namespace {

// Without a given one, the regions are worked out from the tolerance, if there is one.
std::span<const std::uint32_t> regions_of(const DistanceSet& distances,
                                          const ColorizeOptions& options,
                                          std::span<const std::uint32_t> sample_region,
                                          RegionMap& worked_out) {
  if (!sample_region.empty() || !options.tolerance) return sample_region;
  worked_out = map_error_regions(distances.samples, distances.field.distance, *options.tolerance);
  return worked_out.sample_region;
}

std::vector<std::string> ply_comments(const DistanceSet& distances,
                                      const ColorizeOptions& options) {
  return {fmt::format("ncverify {} {}: signed error of {} against {}", NCV_VERSION,
                      name_of(kDirectionNames, distances.direction), distances.samples.source,
                      distances.reference.source),
          "positive = material left (excess), negative = gouge; units " + options.units,
          "scalar_region = k: the k-th out-of-tolerance region of the report (0: none)"};
}

}  // namespace

ColoredSurface colorize(const DistanceSet& distances, const ColorizeOptions& options,
                        std::span<const std::uint32_t> sample_region) {
  const ColorMap map = choose_color_map(distances, options);
  RegionMap regions;
  sample_region = regions_of(distances, options, sample_region, regions);
  const std::span<const double> d = distances.field.distance;
  return {map, options.coarse ? workpiece_error_mesh(distances.samples, d, sample_region)
                              : lattice_error_mesh(distances.samples, d, sample_region)};
}

std::string legend_svg(const ColorMap& map, const DistanceSet& distances,
                       const ColorizeOptions& options) {
  const bool forward = distances.direction == Direction::forward;
  const std::string workpiece = forward ? distances.samples.source : distances.reference.source;
  std::string part = std::filesystem::path(workpiece).stem().string();
  if (!forward) part += " (the nominal against it)";
  const int decimals =
      number_style(bounding_box(distances.samples.mesh), options.units).length_decimals;
  std::ostringstream svg;
  write_legend_svg(svg, map, PictureText{part, options.units, decimals});
  return svg.str();
}

// The PLY is streamed from the samples (the lattice) or the workpiece's mesh and its vertex
// errors (coarse), read in place.
void write_colored(const DistanceSet& distances, const ColorizeOptions& options,
                   const std::string& ply_path, const std::string& legend_path,
                   std::span<const std::uint32_t> sample_region) {
  const ColorMap map = choose_color_map(distances, options);
  RegionMap regions;
  sample_region = regions_of(distances, options, sample_region, regions);
  const std::span<const double> d = distances.field.distance;
  OutputFile out(ply_path, OutputKind::binary);
  std::optional<OutputFile> legend;
  if (!legend_path.empty()) {
    legend.emplace(legend_path, OutputKind::text);
    legend->write(legend_svg(map, distances, options));
  }
  const std::vector<std::string> comments = ply_comments(distances, options);
  std::uint64_t vertices = 0, faces = 0;
  const auto write = [&](const PlyMesh& mesh) {
    write_error_ply(out, mesh, map, comments);
    vertices = mesh.vertex_count();
    faces = mesh.face_offsets().back();
  };
  if (options.coarse) {
    const VertexErrors errors = vertex_errors(distances.samples, d, sample_region);
    write(ErrorMeshPly(distances.samples.mesh, errors.values, errors.regions));
  } else {
    write(LatticeMesh(distances.samples, d, sample_region));
  }
  out.commit();
  if (legend) legend->commit();
  spdlog::info("wrote {} ({} vertices, {} faces, {})", out.display_name(), vertices, faces,
               map.description());
}

void run_colorize(const ColorizeJob& job) {
  const PartDistances part = read_part_distances(job.distances, job.samples);
  if (part.reverse) {
    throw UsageError("colorize paints one direction: give the forward or the reverse files");
  }
  write_colored(part.main, job.options, job.output, job.legend_svg);
}

}  // namespace ncv
