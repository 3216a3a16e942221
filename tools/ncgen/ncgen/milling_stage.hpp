// One stage of the NC process (roughing, semi-finishing, finishing): its cutter, the stock it
// leaves, its raster path spacing, and the deliberate gouges of the data set.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "ncgen/cutter.hpp"

namespace ncv::gen {

// A spot where the cutter plunges below its programmed path, ending `depth` below the nominal
// surface where that is flat.
struct Gouge {
  double x = 0;
  double y = 0;
  double depth = 0;
};

struct MillingStage {
  std::string name;
  Cutter cutter;
  double allowance = 0;  // stock left along the surface normal
  double stepover = 1;   // between pass lines
  double feed = 0.1;     // between tool positions along a pass
  double stepdown = 0;   // z-level roughing step; 0 follows the surface
  std::vector<Gouge> gouges;
  // Triangles of the simulated workpiece at size 1: the paper's Table 1.
  std::size_t paper_triangles = 0;
};

// The mould core's process. Roughing: 10 mm flat end mill in 2 mm z-levels, leaving 0.3 mm
// (and whatever the cutter cannot reach). Semi-finishing: 6 mm ball end, 0.1 mm left.
// Finishing: 3 mm ball end at 0.625 mm stepover (about 0.033 mm scallops). One roughing gouge
// of 0.3 mm on the base and two finishing gouges (0.1 mm on the base, 0.2 mm on the pocket
// floor), all on horizontal faces.
std::vector<MillingStage> mould_core_stages();

}  // namespace ncv::gen
