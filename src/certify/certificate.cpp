#include "certify/certificate.hpp"

#include "geometry/point_json.hpp"

namespace ncv {
namespace {

CertifiedExtreme negated(const CertifiedExtreme& e) {
  return {-e.measured, e.measured_at, -e.bound, e.bound_at};
}

// The later certificate's extreme replaces the earlier one only when strictly beyond it, so
// that ties keep the lowest-numbered place, as in one certificate.
void keep_larger(CertifiedExtreme& into, const CertifiedExtreme& other) {
  if (other.measured > into.measured) {
    into.measured = other.measured;
    into.measured_at = other.measured_at;
  }
  if (other.bound > into.bound) {
    into.bound = other.bound;
    into.bound_at = other.bound_at;
  }
}

void keep_smaller(CertifiedExtreme& into, const CertifiedExtreme& other) {
  if (other.measured < into.measured) {
    into.measured = other.measured;
    into.measured_at = other.measured_at;
  }
  if (other.bound < into.bound) {
    into.bound = other.bound;
    into.bound_at = other.bound_at;
  }
}

}  // namespace

nlohmann::json certified_extreme_json(const CertifiedExtreme& e) {
  return {{"measured", e.measured},
          {"measured_at", point_json(e.measured_at)},
          {"bound", e.bound},
          {"bound_at", point_json(e.bound_at)}};
}

Certificate negated(const Certificate& c) {
  Certificate n = c;
  n.max = negated(c.min);
  n.min = negated(c.max);
  return n;
}

std::optional<Certificate> merged(const Certificate& first, const Certificate& next) {
  if (first.end_anchor != next.first_anchor || first.width_asked != next.width_asked ||
      first.sign_proven != next.sign_proven) {
    return std::nullopt;
  }
  Certificate m = first;
  m.end_anchor = next.end_anchor;
  m.points_cap += next.points_cap;
  keep_larger(m.max, next.max);
  keep_smaller(m.min, next.min);
  m.patches += next.patches;
  m.refined_patches += next.refined_patches;
  m.added_points += next.added_points;
  m.unresolved += next.unresolved;
  return m;
}

}  // namespace ncv
