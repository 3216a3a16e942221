#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <future>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "commands.hpp"
#include "ncgen/analytic_parts.hpp"
#include "ncgen/decimated_parts.hpp"
#include "ncgen/nominal_part.hpp"
#include "ncgen/part_size.hpp"
#include "ncgen/workpiece.hpp"
#include "part_files.hpp"

namespace ncv::gen::app {
namespace {

namespace fs = std::filesystem;

// "semi-finishing" -> "core_semifinishing.stl"
std::string workpiece_file(const MillingStage& stage) {
  std::string name = stage.name;
  name.erase(std::remove(name.begin(), name.end(), '-'), name.end());
  return "core_" + name + ".stl";
}

nlohmann::json mould_core_set(const fs::path& out, std::uint64_t seed, double size) {
  nlohmann::json parts = nlohmann::json::array();
  const MouldCore part = make_mould_core(seed);
  const NominalOptions nominal;
  nlohmann::json json =
      save_mesh(nominal_mesh(part, nominal), out / "core_nominal.stl", "ncgen mould core nominal");
  json["role"] = "nominal";
  json["chord_tolerance"] = nominal.chord_tolerance;
  parts.push_back(json);
  mill_part(part, size, mould_core_stages(),
            [&](const MillingStage& stage, const MillingSimulation& simulation) {
              nlohmann::json workpiece =
                  save_workpiece(stage, simulation, size, out / workpiece_file(stage));
              workpiece["role"] = "workpiece";
              workpiece["nominal"] = "core_nominal.stl";
              parts.push_back(workpiece);
            });
  return parts;
}

// Where the far copies of the decimated family lie: tens of metres from the origin, as in a
// machine's frame, on every axis and on both sides of it.
const Vec3 far_offset{20000, -15000, 5000};

std::string far_file(const std::string& file) {
  return file.substr(0, file.size() - 4) + "_far.stl";
}

// The part written as it is and again shuffled and far from the origin (the nominal moved by
// the same vector, so that the pair still fits); their manifest entries.
nlohmann::json save_near_and_far(const MeshedPart& part, const fs::path& out,
                                 const std::string& file, nlohmann::json fields,
                                 std::uint64_t seed) {
  nlohmann::json both = nlohmann::json::array();
  nlohmann::json json = save_part(part, {}, out / file);
  json.update(fields);
  both.push_back(json);
  if (fields.contains("nominal")) {
    fields["nominal"] = far_file(fields["nominal"].get<std::string>());
  }
  json = save_part(part, {true, seed, far_offset}, out / far_file(file));
  json.update(fields);
  both.push_back(json);
  return both;
}

// The decimated family: the nominal and every stage meshed by decimation, each also shuffled
// and far from the origin. Decimation is serial, so each stage's runs on a thread of its own
// while the simulation mills the next stage and the threads decimate the stages before: the
// large set takes about the finishing stage's decimation instead of the sum of all of them.
nlohmann::json decimated_set(const fs::path& out, std::uint64_t seed, double size) {
  const Meshing meshing{Mesher::decimate, {}};
  const MouldCore part = make_mould_core(seed);
  std::vector<std::future<nlohmann::json>> stages;
  mill_part(part, size, mould_core_stages(),
            [&](const MillingStage& stage, const MillingSimulation& simulation) {
              stages.push_back(std::async(std::launch::async, [=, &out] {
                return save_near_and_far(
                    mesh_workpiece(stage, simulation, size, meshing), out, workpiece_file(stage),
                    {{"role", "workpiece"}, {"nominal", "core_nominal.stl"}}, seed);
              }));
            });
  nlohmann::json parts =
      save_near_and_far(mesh_decimated_nominal(part, decimated_nominal_triangles, meshing), out,
                        "core_nominal.stl", {{"role", "nominal"}}, seed);
  for (std::future<nlohmann::json>& stage : stages) {
    for (const nlohmann::json& json : stage.get()) parts.push_back(json);
  }
  return parts;
}

// Boxes with the signed deviation range a verifier must find against box_nominal.stl.
nlohmann::json box_set(const fs::path& out) {
  const Vec3 size{100, 60, 30};
  const double offset = 0.1;
  const double lift = 0.2;
  const double radius = 1.5;
  const double stepover = 0.625;
  const double scallop = scallop_height(radius, stepover);
  nlohmann::json parts = nlohmann::json::array();
  const auto add = [&](const ncv::Mesh& mesh, const std::string& file, double min, double max,
                       const std::string& what) {
    nlohmann::json json = save_mesh(mesh, out / file, "ncgen " + what);
    json["role"] = file == "box_nominal.stl" ? "nominal" : "workpiece";
    json["nominal"] = "box_nominal.stl";
    json["description"] = what;
    json["expected_min_error"] = min;
    json["expected_max_error"] = max;
    parts.push_back(json);
  };
  add(box_mesh({0, 0, 0}, size), "box_nominal.stl", 0, 0, "box 100 x 60 x 30 mm");
  add(box_mesh({-offset, -offset, -offset}, size + Vec3{offset, offset, offset}), "box_offset.stl",
      offset, offset * std::sqrt(3.0),
      "box with every face 0.1 mm out (errors 0.1 on faces, up to 0.1 sqrt 3 at corners)");
  add(box_mesh({0, 0, 0}, size + Vec3{0, 0, lift}), "box_top_raised.stl", 0, lift,
      "box with the top 0.2 mm up");
  add(box_mesh({0, 0, 0}, size - Vec3{0, 0, lift}), "box_top_lowered.stl", -lift, 0,
      "box with the top 0.2 mm down");
  add(scalloped_box(size, radius, stepover, 4), "box_scallop.stl", 0, scallop,
      "box top cut by a 1.5 mm ball at 0.625 mm stepover");
  return parts;
}

// Nominals with a feature the workpiece lacks, which only the reverse direction measures:
// a slot never cut (forward max = half its width, reverse max = its depth) and a rib cut off
// (forward min = -half its width, reverse min = -its height), all exact in float.
nlohmann::json missing_feature_set(const fs::path& out) {
  const Vec3 size{100, 60, 30};
  const double centre = 30;
  nlohmann::json parts = nlohmann::json::array();
  const auto add = [&](const ncv::Mesh& mesh, const std::string& file, const std::string& nominal,
                       const std::string& what, std::array<double, 4> errors) {
    nlohmann::json json = save_mesh(mesh, out / file, "ncgen " + what);
    json["role"] = file == nominal ? "nominal" : "workpiece";
    json["nominal"] = nominal;
    json["description"] = what;
    if (file != nominal) {
      json["expected_min_error"] = errors[0];
      json["expected_max_error"] = errors[1];
      json["expected_reverse_min_error"] = errors[2];
      json["expected_reverse_max_error"] = errors[3];
    }
    parts.push_back(json);
  };
  const double slot_width = 1, slot_depth = 10, rib_width = 2, rib_height = 5;
  add(grooved_box(size, centre, slot_width, slot_depth), "slot_nominal.stl", "slot_nominal.stl",
      "box 100 x 60 x 30 mm with a slot 1 mm wide and 10 mm deep along x", {});
  add(box_with_top_lines(size, {centre - slot_width / 2, centre, centre + slot_width / 2}),
      "slot_uncut.stl", "slot_nominal.stl", "the box without its slot",
      {0, slot_width / 2, 0, slot_depth});
  add(grooved_box(size, centre, rib_width, -rib_height), "rib_nominal.stl", "rib_nominal.stl",
      "box 100 x 60 x 30 mm with a rib 2 mm wide and 5 mm high along x", {});
  add(box_with_top_lines(size, {centre - rib_width / 2, centre, centre + rib_width / 2}),
      "rib_missing.stl", "rib_nominal.stl", "the box without its rib",
      {-rib_width / 2, 0, -rib_height, 0});
  return parts;
}

}  // namespace

void add_all_command(CLI::App& app, const GlobalOptions& global) {
  struct Options {
    std::string out;
    std::string size = "small";
    std::string family = "rtin";
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "all",
      "The whole data set: mould core nominal and workpieces, analytic boxes, and "
      "manifest.json describing them");
  command->add_option("--out", options->out, "Directory to write into")->required();
  command->add_option("--size", options->size, "Workpiece size: small, medium, large or factor")
      ->capture_default_str();
  command
      ->add_option("--family", options->family,
                   "rtin: the mould core set, boxes and missing features; decimated: the mould "
                   "core meshed by decimation, each part also shuffled and far from the origin")
      ->capture_default_str()
      ->check(CLI::IsMember({"rtin", "decimated"}));
  command->callback([options, &global] {
    const double size = parse_size(options->size);
    const fs::path out = options->out;
    fs::create_directories(out);
    nlohmann::json parts;
    if (options->family == "decimated") {
      parts = decimated_set(out, global.seed, size);
    } else {
      parts = mould_core_set(out, global.seed, size);
      for (const nlohmann::json& box : box_set(out)) parts.push_back(box);
      for (const nlohmann::json& part : missing_feature_set(out)) parts.push_back(part);
    }
    nlohmann::json manifest = {{"generator", "ncgen"},
                               {"seed", global.seed},
                               {"size", options->size},
                               {"size_factor", size},
                               {"parts", parts}};
    if (options->family != "rtin") manifest["family"] = options->family;
    write_json(manifest, out / "manifest.json");
  });
}

}  // namespace ncv::gen::app
