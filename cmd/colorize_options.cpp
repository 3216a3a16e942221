#include "colorize_options.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "option_checks.hpp"
#include "render/color_map.hpp"
#include "render/error_mesh.hpp"
#include "render/ply_writer.hpp"
#include "render/svg_legend.hpp"
#include "report_options.hpp"
#include "util/output_file.hpp"

namespace ncv::cmd {
namespace {

// Without --range: for the tolerance map the data's extent (at least the zone), so the
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

ColorMap choose_map(const DistanceSet& distances, const ColorizeOptions& options) {
  const std::optional<Tolerance> tolerance = parse_tolerance_option(options.tolerance);
  const ColorMapKind kind = options.map.empty()
                                ? (tolerance ? ColorMapKind::tolerance : ColorMapKind::diverging)
                                : parse_color_map_kind(options.map);
  if (kind == ColorMapKind::tolerance && !tolerance) {
    throw UsageError("the tolerance colour map needs a tolerance: give --tol");
  }
  ValueRange range;
  if (options.range.empty()) {
    range = default_range(distances, kind, tolerance);
  } else {
    range = parse_value_range(options.range);
  }
  return make_color_map(kind, range, tolerance);
}

}  // namespace

void add_colorize_options(CLI::App& sub, ColorizeOptions& options) {
  sub.add_option("--map", options.map,
                 "Colour map: tolerance (green within, red excess, blue gouge), diverging "
                 "(blue-white-red) or turbo; default: tolerance when --tol is given")
      ->check(CLI::IsMember({"tolerance", "diverging", "turbo"}));
  sub.add_option("--range", options.range,
                 "Values the colour map spans, LO:HI or R for ±R (default: from the data)")
      ->check(valid_range());
  sub.add_flag("--refine", options.refine,
               "Write the sampling lattice as the mesh, so every sample's error shows");
  sub.add_option("--legend", options.legend_svg, "Also write the colour bar as SVG");
}

void write_colorized(const DistanceSet& distances, const std::string& ply_path,
                     const ColorizeOptions& options) {
  const ColorMap map = choose_map(distances, options);
  const ErrorMesh mesh = options.refine
                             ? lattice_error_mesh(distances.samples, distances.field.distance)
                             : workpiece_error_mesh(distances.samples, distances.field.distance);
  const std::string comments[] = {"ncverify " NCV_VERSION " signed error of " +
                                      distances.samples.workpiece_source + " against " +
                                      distances.nominal.source,
                                  "positive = excess material, negative = gouge"};
  const Buffer<char> ply = error_ply(mesh, map, comments);
  // Both outputs open before either is committed: a legend path that cannot be written
  // leaves no coloured mesh either.
  OutputFile out(ply_path, OutputKind::binary);
  std::optional<OutputFile> legend;
  if (!options.legend_svg.empty()) {
    legend.emplace(options.legend_svg, OutputKind::text);
    std::ostringstream svg;
    write_legend_svg(svg, map, "model units");
    legend->write(svg.str());
  }
  out.write(ply.data(), ply.size());
  out.commit();
  if (legend) legend->commit();
  spdlog::info("wrote {} ({} vertices, {} faces, {})", out.display_name(), mesh.mesh.vertex_count(),
               mesh.mesh.triangle_count(), map.description());
}

}  // namespace ncv::cmd
