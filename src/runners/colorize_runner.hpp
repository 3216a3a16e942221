// The colorize step (`ncverify colorize`, and run's colorize phase): the sampled surface
// painted by its error as a binary PLY for MeshLab and CloudCompare, and the colour bar as SVG
// (docs/METHOD.md "Colouring").
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "files/distance_file.hpp"
#include "render/color_map.hpp"
#include "render/error_mesh.hpp"
#include "statistics/tolerance.hpp"
#include "statistics/value_range.hpp"

namespace ncv {

struct ColorizeOptions {
  std::optional<Tolerance> tolerance;  // marks the zone; selects the tolerance map by default
  std::optional<ColorMapKind> map;     // default: tolerance with a tolerance, else diverging
  std::optional<ValueRange> range;     // default: from the data (see choose_color_map)
  // The sampled mesh's own vertices only (a small file), instead of the sampling lattice
  // with every sample a vertex (the default: the worst point is in the picture).
  bool coarse = false;
  std::string units = "mm";  // named in the legend and the PLY's comments
};

// Throws UsageError for the tolerance map without a tolerance.
ColorMap choose_color_map(const DistanceSet& distances, const ColorizeOptions& options);

struct ColoredSurface {
  ColorMap map;
  ErrorMesh mesh;
};
// sample_region: per sample, its out-of-tolerance region (statistics/error_regions.hpp), for
// the PLY's region property; empty: worked out here from the tolerance, if there is one.
ColoredSurface colorize(const DistanceSet& distances, const ColorizeOptions& options,
                        std::span<const std::uint32_t> sample_region = {});
std::string legend_svg(const ColorMap& map, const DistanceSet& distances,
                       const ColorizeOptions& options);

// Writes the PLY (and the legend when `legend_svg` is not empty); both are opened before
// either is committed, so a legend path that cannot be written leaves no PLY either.
void write_colored(const DistanceSet& distances, const ColorizeOptions& options,
                   const std::string& ply_path, const std::string& legend_path,
                   std::span<const std::uint32_t> sample_region = {});

// `ncverify colorize DIST... -o OUT.ply`.
struct ColorizeJob {
  std::vector<std::string> distances;  // one direction: one file, or every shard of its job
  std::string samples;                 // the samples file of a single distance file
  std::string output;
  std::string legend_svg;  // empty: none
  ColorizeOptions options;
};
void run_colorize(const ColorizeJob& job);

}  // namespace ncv
