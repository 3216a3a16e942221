#include "part_files.hpp"

#include <spdlog/spdlog.h>

#include <fstream>
#include <stdexcept>
#include <string>

#include "ncgen/analytic_parts.hpp"
#include "ncgen/stl_writer.hpp"
#include "ncgen/workpiece.hpp"

namespace ncv::gen::app {

nlohmann::json save_mesh(const ncv::Mesh& mesh, const std::filesystem::path& path,
                         std::string_view header) {
  write_binary_stl(mesh, path, header);
  const BoundingBox box = bounding_box(mesh);
  spdlog::info("wrote {} ({} triangles)", path.string(), mesh.triangle_count());
  return {{"file", path.filename().string()},
          {"triangles", mesh.triangle_count()},
          {"vertices", mesh.vertex_count()},
          {"bounds", {{box.min[0], box.min[1], box.min[2]}, {box.max[0], box.max[1], box.max[2]}}}};
}

namespace {

nlohmann::json describe_stage(const MillingStage& stage) {
  nlohmann::json json = {{"stage", stage.name},
                         {"cutter", std::string(shape_name(stage.cutter.shape))},
                         {"cutter_radius", stage.cutter.radius},
                         {"allowance", stage.allowance},
                         {"stepover", stage.stepover},
                         {"feed_step", stage.feed}};
  if (stage.stepdown > 0) json["stepdown"] = stage.stepdown;
  if (stage.cutter.shape == CutterShape::ball_end) {
    json["scallop_height"] = scallop_height(stage.cutter.radius, stage.stepover);
  }
  return json;
}

nlohmann::json describe_gouges(const std::vector<GougeRecord>& gouges) {
  nlohmann::json list = nlohmann::json::array();
  for (const GougeRecord& gouge : gouges) {
    list.push_back({{"stage", gouge.stage},
                    {"x", gouge.x},
                    {"y", gouge.y},
                    {"depth", gouge.depth},
                    {"nominal_z", gouge.nominal_z},
                    {"bottom_z", gouge.nominal_z - gouge.depth},
                    {"cutter", std::string(shape_name(gouge.cutter.shape))},
                    {"cutter_radius", gouge.cutter.radius}});
  }
  return list;
}

}  // namespace

nlohmann::json save_workpiece(const MillingStage& stage, const MillingSimulation& simulation,
                              double size, const std::filesystem::path& path) {
  const Workpiece workpiece = workpiece_mesh(simulation, workpiece_triangles(stage, size));
  nlohmann::json json = save_mesh(workpiece.mesh, path, "ncgen mould core " + stage.name);
  json.update(describe_stage(stage));
  json["chord_tolerance"] = workpiece.tolerance;
  json["zmap_spacing"] = simulation.grid().spacing;
  json["gouges"] = describe_gouges(simulation.gouges());
  return json;
}

void write_json(const nlohmann::json& json, const std::filesystem::path& path) {
  std::ofstream file(path);
  file << json.dump(2) << '\n';
  if (!file) throw std::runtime_error("cannot write " + path.string());
  spdlog::info("wrote {}", path.string());
}

std::size_t stage_index(std::string_view name) {
  if (name == "roughing") return 0;
  if (name == "semi" || name == "semi-finishing" || name == "semifinishing") return 1;
  if (name == "finishing") return 2;
  throw std::invalid_argument("unknown stage " + std::string(name));
}

}  // namespace ncv::gen::app
