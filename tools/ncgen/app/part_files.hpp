// Writes generated parts as binary STL, each with a JSON description of what it is and what a
// verifier should find on it.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/mesh.hpp"
#include "ncgen/decimated_parts.hpp"
#include "ncgen/milling_simulation.hpp"
#include "ncgen/milling_stage.hpp"
#include "ncgen/mould_core.hpp"
#include "ncgen/placement.hpp"

namespace ncv::gen::app {

// How a part's surface becomes triangles: the RTIN of its heights (the first family) or a
// fine RTIN decimated by OpenMesh (the second, decimated_parts.hpp); then where it is put.
enum class Mesher { rtin, decimate };

struct Meshing {
  Mesher mesher = Mesher::rtin;
  DecimatedOptions decimated;
};

// A part meshed, not yet placed or written: its triangles, what the manifest says of it and
// the STL header.
struct MeshedPart {
  ncv::Mesh mesh;
  nlohmann::json description;
  std::string header;
};

// "rtin" | "decimate"; throws std::invalid_argument otherwise.
Mesher parse_mesher(std::string_view name);

// Writes the STL and returns {"file", "triangles", "vertices", "bounds"}.
nlohmann::json save_mesh(const ncv::Mesh& mesh, const std::filesystem::path& path,
                         std::string_view header);

// Meshes the simulation's Z-map after `stage` at a size, described with the stage's process
// parameters, every gouge so far and how it was meshed.
MeshedPart mesh_workpiece(const MillingStage& stage, const MillingSimulation& simulation,
                          double size, const Meshing& meshing);

// The decimated nominal, about `triangles`.
MeshedPart mesh_decimated_nominal(const MouldCore& part, std::size_t triangles,
                                  const Meshing& meshing);

// Writes a copy of the part placed as asked; returns its manifest entry.
nlohmann::json save_part(const MeshedPart& part, const Placement& placement,
                         const std::filesystem::path& path);

// mesh_workpiece, then save_part.
nlohmann::json save_workpiece(const MillingStage& stage, const MillingSimulation& simulation,
                              double size, const std::filesystem::path& path,
                              const Meshing& meshing = {}, const Placement& placement = {});

void write_json(const nlohmann::json& json, const std::filesystem::path& path);

// Stage index for roughing | semi | semi-finishing | semifinishing | finishing.
std::size_t stage_index(std::string_view name);

}  // namespace ncv::gen::app
