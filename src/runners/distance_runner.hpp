// The distance step (`ncverify distance`, and run's distance phase in each direction): every
// sample's signed distance to the reference surface (docs/METHOD.md "Signed distance"), after
// checking that the two belong together.
#pragma once

#include <optional>
#include <string>

#include "certify/certify_surface.hpp"
#include "distance/direction.hpp"
#include "files/distance_file.hpp"
#include "reference/sign_method.hpp"
#include "sampling/sampling.hpp"
#include "search/indexed_reference.hpp"
#include "search/search_index.hpp"

namespace ncv {

struct DistanceOptions {
  SignMethod sign = SignMethod::automatic;
  bool brute_force = false;  // test every reference triangle (the reference result), no grid
  // forward: the workpiece's samples against the nominal; reverse: the nominal's samples
  // against the workpiece, signed so that + is still material left (distance/direction.hpp).
  Direction direction = Direction::forward;
  // Bounds on the error between the samples (docs/CERTIFICATION.md); none: not certified,
  // and then no verdict can be `pass`.
  std::optional<CertifyOptions> certify = CertifyOptions{};
};

// Refuses (InputError naming the workpiece) a workpiece farther from the nominal than the
// size of either part, from the two meshes' bounding boxes, so that `run` can refuse before
// sampling.
void refuse_if_apart(const BoundingBox& workpiece, const std::string& workpiece_source,
                     const BoundingBox& nominal, const std::string& nominal_source);

// The same refusal, then warnings where the parts look mixed up: the same mesh twice, little
// overlap, sizes five times apart (named when the factor is an inch or a metre), a workpiece
// far coarser than its nominal (given the other way round?). Called once per part.
void check_parts(const Mesh& workpiece, const std::string& workpiece_source, const Mesh& nominal,
                 const std::string& nominal_source);

// The refusal, then measures every sample against the index's reference; `seconds` receives
// the time the measuring took.
DistanceSet measure_distances(SampleSet samples, const SearchIndex& index,
                              const DistanceOptions& options, double* seconds = nullptr);
// Samples per second, triangles tested per sample and the sign method, on stderr.
void log_distances(const DistanceSet& distances, double seconds);

// `ncverify distance SAMPLES GRID -o OUT`.
struct DistanceJob {
  std::string samples;
  std::string grid;
  std::string output;
  DistanceOptions options;
};
void run_distance(const DistanceJob& job);

}  // namespace ncv
