// The distance step as the commands run it: samples + grid in, a DistanceSet out, with the
// overlap check, the progress bar and the report on the way.
#pragma once

#include "files/distance_file.hpp"
#include "files/grid_file.hpp"
#include "sampling/sampling.hpp"
#include "search/search_index.hpp"

namespace ncv {

struct DistanceStepOptions {
  SignMethod sign = SignMethod::automatic;
  bool brute_force = false;  // test every nominal triangle (the reference), no grid
};

// Refuses (InputError) a workpiece farther from the nominal than the size of either part,
// from the two meshes' bounding boxes, so that `run` can refuse before sampling; throws
// InputError naming the workpiece source.
void refuse_if_apart(const BoundingBox& workpiece, const std::string& workpiece_source,
                     const BoundingBox& nominal, const std::string& nominal_source);
// The same refusal; then warns when they barely overlap, differ in size five times or are
// the same mesh (a wrong file, unit or frame?), then measures every sample; `seconds`
// receives the time the measuring took. `search` is made from grid.nominal's corners and
// grid.grid (not read with brute_force).
DistanceSet measure_distances(SampleSet samples, const PreparedNominal& grid,
                              const SearchIndex& search, const DistanceStepOptions& options,
                              double* seconds = nullptr);
// Samples per second, triangles tested per sample and the sign method, on stderr.
void log_distance_report(const DistanceSet& distances, double seconds);

}  // namespace ncv
