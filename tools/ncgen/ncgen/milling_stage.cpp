#include "ncgen/milling_stage.hpp"

namespace ncv::gen {

std::vector<MillingStage> mould_core_stages() {
  MillingStage roughing{"roughing", {CutterShape::flat_end, 5.0}, 0.3, 6.25, 0.3125, 2.0, {}, 0};
  roughing.gouges = {{6.25, 75.0, 0.3}};
  roughing.paper_triangles = 214'822;
  MillingStage semi{"semi-finishing", {CutterShape::ball_end, 3.0}, 0.1, 1.25, 0.15625, 0, {}, 0};
  semi.paper_triangles = 470'537;
  MillingStage finishing{"finishing", {CutterShape::ball_end, 1.5}, 0.0, 0.625, 0.078125, 0, {}, 0};
  finishing.gouges = {{60.0, 8.125, 0.1}, {100.0, 17.5, 0.2}};
  finishing.paper_triangles = 1'239'420;
  return {roughing, semi, finishing};
}

}  // namespace ncv::gen
