#include "statistics/verdict.hpp"

#include <fmt/format.h>

namespace ncv {
namespace {

// The measured extremes: the samples', and the points certification added.
double measured_max(const ErrorStatistics& s, const std::optional<Certificate>& c) {
  return c ? std::max(s.max.value, c->max.measured) : s.max.value;
}
double measured_min(const ErrorStatistics& s, const std::optional<Certificate>& c) {
  return c ? std::min(s.min.value, c->min.measured) : s.min.value;
}

}  // namespace

Verdict judge(const ErrorStatistics& s, const std::optional<Certificate>& c, const Tolerance& t) {
  if (measured_max(s, c) > t.upper || measured_min(s, c) < t.lower) return Verdict::fail;
  if (!c || s.triangles_unsampled > 0) return Verdict::inconclusive;
  if (c->max.bound <= t.upper && c->min.bound >= t.lower) return Verdict::pass;
  return Verdict::inconclusive;
}

Verdict worse(Verdict a, Verdict b) {
  if (a == Verdict::fail || b == Verdict::fail) return Verdict::fail;
  if (a == Verdict::inconclusive || b == Verdict::inconclusive) return Verdict::inconclusive;
  return Verdict::pass;
}

std::string verdict_reason(const ErrorStatistics& s, const std::optional<Certificate>& c,
                           const Tolerance& t, const NumberStyle& n) {
  const double max = measured_max(s, c), min = measured_min(s, c);
  switch (judge(s, c, t)) {
    case Verdict::fail: {
      std::vector<std::string> parts;
      if (max > t.upper) {
        parts.push_back(
            fmt::format("max {} above the upper limit {}", n.length_with_units(max), t.upper));
      }
      if (min < t.lower) {
        parts.push_back(
            fmt::format("min {} below the lower limit {}", n.length_with_units(min), t.lower));
      }
      return fmt::format("measured {}", fmt::join(parts, ", "));
    }
    case Verdict::pass:
      return fmt::format(
          "proven within [{}, {}] everywhere, not only at the samples: the error lies between {} "
          "and {}",
          t.lower, t.upper, n.length_with_units(c->min.bound), n.length_with_units(c->max.bound));
    case Verdict::inconclusive:
      break;
  }
  if (!c) {
    return "nothing bounds the error between the samples (measured without certification); "
           "measure again to certify";
  }
  if (s.triangles_unsampled > 0) {
    return fmt::format(
        "{} triangles were not sampled (scheme paper-ii), so nothing bounds the error there",
        s.triangles_unsampled);
  }
  std::vector<std::string> parts;
  if (c->max.bound > t.upper) {
    parts.push_back(fmt::format(
        "may reach {} near {}, above the upper limit {} by at most {} (measured max {})",
        n.length_with_units(c->max.bound), n.point(c->max.bound_at), t.upper,
        n.length_with_units(c->max.bound - t.upper), n.length(max)));
  }
  if (c->min.bound < t.lower) {
    parts.push_back(fmt::format(
        "may reach {} near {}, below the lower limit {} by at most {} (measured min {})",
        n.length_with_units(c->min.bound), n.point(c->min.bound_at), t.lower,
        n.length_with_units(t.lower - c->min.bound), n.length(min)));
  }
  std::string reason =
      fmt::format("every measured point is within tolerance, but between samples the error {}",
                  fmt::join(parts, "; and "));
  if (c->unresolved > 0) {
    reason += fmt::format(" ({} sub-triangles still unresolved at the refinement cap of {} points)",
                          c->unresolved, c->points_cap);
  }
  if (!c->sign_proven) reason += "; the side is proven only against a closed nominal";
  return reason;
}

}  // namespace ncv
