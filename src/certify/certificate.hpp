// What certification proves about the signed error over the whole sampled surface, not only
// at its samples (docs/CERTIFICATION.md): for the largest and the smallest error, an
// interval that contains the true value. Its inner end is a measured point (a lattice sample
// or a point refinement added), its outer end a bound proven over every lattice
// sub-triangle: measured max <= true max <= max bound, min bound <= true min <= measured min.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "geometry/vec3.hpp"

namespace ncv {

struct CertifiedExtreme {
  double measured = 0;  // the most extreme error at a measured point
  Vec3 measured_at{0, 0, 0};
  double bound = 0;        // proven: no point of the surface goes beyond it
  Vec3 bound_at{0, 0, 0};  // centre of the sub-triangle whose bound this is

  double width() const { return bound > measured ? bound - measured : measured - bound; }
};

struct Certificate {
  double width_asked = 0;             // --certify: the interval width refinement aims at
  std::uint64_t points_cap = 0;       // the most points refinement may add
  CertifiedExtreme max;               // bound >= measured
  CertifiedExtreme min;               // bound <= measured
  std::uint64_t patches = 0;          // lattice sub-triangles bounded
  std::uint64_t refined_patches = 0;  // of them, split at least once
  std::uint64_t added_points = 0;     // points refinement measured
  std::uint64_t unresolved = 0;  // sub-triangles still wider than asked when refinement stopped
  // The side of the reference surface is proven constant inside a sub-triangle only for the
  // pseudonormal sign of a closed, oriented surface; otherwise a sub-triangle whose error
  // could change sign is bounded by +-|d| alone.
  bool sign_proven = false;
  // Shards: the sampled mesh's triangles this certificate covers, by their anchor sample
  // (certify_surface.hpp); the whole job covers every triangle.
  std::uint64_t first_anchor = 0;
  std::uint64_t end_anchor = 0;
};

// An extreme's four fields as the distance file and the report both write them.
nlohmann::json certified_extreme_json(const CertifiedExtreme& extreme);

// The certificate of the other direction's convention: reverse distances are the negated
// signed distances to the workpiece, so max and min swap and change sign.
Certificate negated(const Certificate& certificate);

// Two shards' certificates as one: the anchors must follow on; extremes combine, counts add.
// Returns nothing when the anchors do not follow on.
std::optional<Certificate> merged(const Certificate& first, const Certificate& next);

}  // namespace ncv
