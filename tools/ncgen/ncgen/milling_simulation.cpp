#include "ncgen/milling_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "ncgen/raster_milling.hpp"

namespace ncv::gen {
namespace {

// Z-level roughing cuts each level only where the cutter may go that deep: a tip is raised to
// the lowest level at or above it. Tips are floats, so a tip within rounding of a level (a flat
// face plus allowance) counts as on it.
void raise_to_levels(std::vector<float>& tips, const std::vector<float>& levels) {
  constexpr float rounding = 1e-4f;
  for (float& tip : tips) {
    const auto level = std::lower_bound(levels.begin(), levels.end(), tip - rounding);
    if (level != levels.end()) tip = std::max(tip, *level);
  }
}

int nearest_index(double coordinate, double spacing, int first, int step, int count) {
  const auto k = std::lround((coordinate / spacing - first) / step);
  return static_cast<int>(std::clamp<long>(k, 0, count - 1));
}

}  // namespace

MillingSimulation::MillingSimulation(const Grid& grid, std::vector<float> nominal,
                                     std::vector<double> flat_levels, double stock_top)
    : grid_(grid),
      nominal_(std::move(nominal)),
      flat_levels_(std::move(flat_levels)),
      stock_top_(stock_top),
      zmap_(grid.sample_count(), static_cast<float>(stock_top)) {}

std::vector<float> MillingSimulation::z_levels(const MillingStage& stage) const {
  std::vector<float> levels;
  for (double z = stock_top_ - stage.stepdown; z > 0; z -= stage.stepdown) {
    levels.push_back(static_cast<float>(z));
  }
  for (double flat : flat_levels_) levels.push_back(static_cast<float>(flat + stage.allowance));
  std::sort(levels.begin(), levels.end());
  return levels;
}

void MillingSimulation::mill(const MillingStage& stage) {
  const double reach = stage.cutter.radius + stage.allowance;
  const RasterPath path = raster_path(grid_, reach, stage.stepover, stage.feed);
  std::vector<float> tips = cutter_locations(
      grid_, nominal_, path, clearance_kernel(stage.cutter, stage.allowance, grid_.spacing));
  if (stage.stepdown > 0) raise_to_levels(tips, z_levels(stage));

  for (const Gouge& gouge : stage.gouges) {
    const int pass =
        nearest_index(gouge.y, grid_.spacing, path.first_row, path.row_step, path.rows);
    const int position =
        nearest_index(gouge.x, grid_.spacing, path.first_col, path.col_step, path.cols);
    tips[static_cast<std::size_t>(pass) * path.cols + position] -=
        static_cast<float>(stage.allowance + gouge.depth);
    const int i = path.col(position);
    const int j = path.row(pass);
    if (!grid_.contains(i, j)) throw std::invalid_argument("gouge outside the part");
    gouges_.push_back({stage.name, grid_.x(i), grid_.y(j), gouge.depth, nominal_[grid_.index(i, j)],
                       stage.cutter});
  }
  cut(grid_, zmap_, path, tips, surface_kernel(stage.cutter, grid_.spacing));
}

}  // namespace ncv::gen
