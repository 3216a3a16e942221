// Simulated 3-axis milling of a stock block on a Z-map. Each stage lowers the heights to the
// lower envelope of its cutter along a raster path whose cutter locations keep the stage's
// allowance from the nominal surface; stages apply in order to the same Z-map.
#pragma once

#include <string>
#include <vector>

#include "ncgen/grid.hpp"
#include "ncgen/milling_stage.hpp"

namespace ncv::gen {

struct GougeRecord {
  std::string stage;
  double x = 0;  // where the cutter plunged: the path position nearest the request
  double y = 0;
  double depth = 0;  // below the nominal surface (exact where that is flat)
  double nominal_z = 0;
  Cutter cutter;
};

class MillingSimulation {
 public:
  // `nominal` holds the part's heights on `grid`; `flat_levels` are the heights of its
  // horizontal faces, which z-level roughing cuts at besides its regular levels.
  MillingSimulation(const Grid& grid, std::vector<float> nominal, std::vector<double> flat_levels,
                    double stock_top);

  void mill(const MillingStage& stage);

  const Grid& grid() const { return grid_; }
  const std::vector<float>& zmap() const { return zmap_; }
  const std::vector<float>& nominal() const { return nominal_; }
  const std::vector<GougeRecord>& gouges() const { return gouges_; }

 private:
  std::vector<float> z_levels(const MillingStage& stage) const;

  Grid grid_;
  std::vector<float> nominal_;
  std::vector<double> flat_levels_;
  double stock_top_;
  std::vector<float> zmap_;
  std::vector<GougeRecord> gouges_;
};

}  // namespace ncv::gen
