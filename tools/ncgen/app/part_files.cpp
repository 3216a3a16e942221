#include "part_files.hpp"

#include <spdlog/spdlog.h>

#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>

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

// The paper's sampling step δ = 0.15 mm leaves a triangle of less than about 0.042 mm²
// unsampled (n = 0 in its eq. 1); the share of such triangles is what makes a mesh hard.
constexpr double tiny_triangle_area = 0.042;

nlohmann::json describe_decimation(const DecimatedSolid& solid, const Meshing& meshing) {
  std::size_t tiny = 0;
  for (std::size_t t = 0; t < solid.mesh.triangle_count(); ++t) {
    if (triangle_area(solid.mesh, t) < tiny_triangle_area) ++tiny;
  }
  return {{"mesher", "decimate"},
          {"fine_triangles", solid.fine_triangles},
          {"fine_chord_tolerance", solid.fine_tolerance},
          {"decimation_tolerance", solid.tolerance},
          {"collapses", solid.collapses},
          {"refinement", meshing.decimated.refinement},
          {"triangles_under_0.042_mm2", tiny},
          {"share_under_0.042_mm2",
           static_cast<double>(tiny) / static_cast<double>(solid.mesh.triangle_count())}};
}

nlohmann::json describe_placement(const Placement& placement) {
  nlohmann::json json = nlohmann::json::object();
  if (placement.shuffle) json["shuffle_seed"] = placement.seed;
  const Vec3& v = placement.offset;
  if (v[0] != 0 || v[1] != 0 || v[2] != 0) json["shift"] = {v[0], v[1], v[2]};
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

Mesher parse_mesher(std::string_view name) {
  if (name == "rtin") return Mesher::rtin;
  if (name == "decimate") return Mesher::decimate;
  throw std::invalid_argument("unknown mesher " + std::string(name) + " (rtin or decimate)");
}

MeshedPart mesh_workpiece(const MillingStage& stage, const MillingSimulation& simulation,
                          double size, const Meshing& meshing) {
  const std::size_t triangles = workpiece_triangles(stage, size);
  MeshedPart part;
  part.header = "ncgen mould core " + stage.name;
  if (meshing.mesher == Mesher::rtin) {
    Workpiece workpiece = workpiece_mesh(simulation, triangles);
    part.description["chord_tolerance"] = workpiece.tolerance;
    part.mesh = std::move(workpiece.mesh);
  } else {
    DecimatedSolid solid = decimated_workpiece_mesh(simulation, triangles, meshing.decimated);
    part.description = describe_decimation(solid, meshing);
    part.mesh = std::move(solid.mesh);
  }
  part.description.update(describe_stage(stage));
  part.description["zmap_spacing"] = simulation.grid().spacing;
  part.description["gouges"] = describe_gouges(simulation.gouges());
  return part;
}

MeshedPart mesh_decimated_nominal(const MouldCore& part, std::size_t triangles,
                                  const Meshing& meshing) {
  DecimatedSolid solid = decimated_nominal_mesh(part, triangles, meshing.decimated);
  nlohmann::json description = describe_decimation(solid, meshing);
  return {std::move(solid.mesh), std::move(description), "ncgen mould core nominal, decimated"};
}

nlohmann::json save_part(const MeshedPart& part, const Placement& placement,
                         const std::filesystem::path& path) {
  ncv::Mesh mesh = part.mesh;
  place(mesh, placement);
  nlohmann::json json = save_mesh(mesh, path, part.header);
  json.update(part.description);
  json.update(describe_placement(placement));
  return json;
}

nlohmann::json save_workpiece(const MillingStage& stage, const MillingSimulation& simulation,
                              double size, const std::filesystem::path& path,
                              const Meshing& meshing, const Placement& placement) {
  return save_part(mesh_workpiece(stage, simulation, size, meshing), placement, path);
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
