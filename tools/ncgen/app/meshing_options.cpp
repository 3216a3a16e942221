#include "meshing_options.hpp"

namespace ncv::gen::app {

Meshing MeshingOptions::meshing() const {
  return {parse_mesher(mesher), decimated};
}

Placement MeshingOptions::placement(std::uint64_t seed) const {
  return {shuffle, seed, {shift[0], shift[1], shift[2]}};
}

void add_meshing_options(CLI::App& command, MeshingOptions& options) {
  command
      .add_option("--mesher", options.mesher,
                  "rtin (right-triangulated irregular network) or decimate (a finer RTIN reduced "
                  "by OpenMesh's quadric decimater, as CAM systems export)")
      ->capture_default_str()
      ->check(CLI::IsMember({"rtin", "decimate"}));
  command
      .add_option("--refinement", options.decimated.refinement,
                  "decimate: triangles of the fine RTIN per triangle wanted")
      ->capture_default_str()
      ->check(CLI::Range(1.0, 16.0));
  command
      .add_option("--tolerance-factor", options.decimated.tolerance_factor,
                  "decimate: distance bound of each collapse, in chord tolerances of an RTIN "
                  "with as many triangles")
      ->capture_default_str()
      ->check(CLI::Range(0.01, 100.0));
  command.add_flag("--shuffle", options.shuffle,
                   "Writes the triangles in a random order (fixed by --seed)");
  command.add_option("--shift", options.shift, "Moves the part by X Y Z mm")->capture_default_str();
}

}  // namespace ncv::gen::app
