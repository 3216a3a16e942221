// Writes generated parts as binary STL, each with a JSON description of what it is and what a
// verifier should find on it.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string_view>
#include <vector>

#include "mesh/mesh.hpp"
#include "ncgen/milling_simulation.hpp"
#include "ncgen/milling_stage.hpp"

namespace ncv::gen::app {

// Writes the STL and returns {"file", "triangles", "vertices", "bounds"}.
nlohmann::json save_mesh(const ncv::Mesh& mesh, const std::filesystem::path& path,
                         std::string_view header);

// Meshes the simulation's Z-map after `stage` at a size, writes it, and describes it with the
// stage's process parameters and every gouge so far.
nlohmann::json save_workpiece(const MillingStage& stage, const MillingSimulation& simulation,
                              double size, const std::filesystem::path& path);

void write_json(const nlohmann::json& json, const std::filesystem::path& path);

// Stage index for roughing | semi | semi-finishing | semifinishing | finishing.
std::size_t stage_index(std::string_view name);

}  // namespace ncv::gen::app
