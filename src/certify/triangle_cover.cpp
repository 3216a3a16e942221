#include "certify/triangle_cover.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace ncv {
namespace {

// Height map cells per patch-sized area at most: the map stays the size of the lattice.
constexpr std::size_t kMaxMapCells = std::size_t{1} << 22;

// The points of the triangle straight below the corners of `flat` (and the middles of their
// edges) that stand farther than `beyond` from its plane, the farthest first, without
// repeats, as many as allowed.
std::vector<Vec3> points_below(const TriangleCorners& triangle,
                               std::span<const TriangleCorners> reference,
                               std::span<const std::uint32_t> flat,
                               const TriangleCoverOptions& options) {
  const Vec3 a = triangle[0];
  const Vec3 n = normalized(cross(triangle[1] - a, triangle[2] - a));
  std::vector<std::pair<double, Vec3>> found;
  const auto offer = [&](Vec3 v) {
    const double h = dot(n, v - a);
    if (!(std::fabs(h) > options.beyond)) return;
    const Vec3 p = v - h * n;
    // Inside the triangle (or on it): the three edge tests agree in sign with the normal.
    bool inside = true;
    for (int k = 0; k < 3 && inside; ++k) {
      inside = dot(n, cross(triangle[(k + 1) % 3] - triangle[k], p - triangle[k])) >= 0;
    }
    if (inside) found.emplace_back(std::fabs(h), p);
  };
  for (const std::uint32_t t : flat) {
    const TriangleCorners& r = reference[t];
    // Its corners, and the middle of an edge whose two ends both stand out: a crest line
    // between two far corners.
    for (int k = 0; k < 3; ++k) {
      offer(r[k]);
      const Vec3& q = r[(k + 1) % 3];
      if (std::fabs(dot(n, r[k] - a)) > options.beyond &&
          std::fabs(dot(n, q - a)) > options.beyond) {
        offer(0.5 * (r[k] + q));
      }
    }
  }
  std::sort(found.begin(), found.end(), [](const auto& x, const auto& y) {
    if (x.first != y.first) return x.first > y.first;
    return std::tie(x.second[0], x.second[1], x.second[2]) <
           std::tie(y.second[0], y.second[1], y.second[2]);
  });
  found.erase(std::unique(found.begin(), found.end(),
                          [](const auto& x, const auto& y) { return x.second == y.second; }),
              found.end());
  if (found.size() > options.max_points) found.resize(options.max_points);
  std::vector<Vec3> points;
  points.reserve(found.size());
  for (const auto& [h, p] : found) points.push_back(p);
  return points;
}

}  // namespace

std::optional<TriangleCover> TriangleCover::build(const TriangleCorners& triangle,
                                                  NearbyTriangles& nearby,
                                                  const SideWitness& witness,
                                                  const TriangleCoverOptions& options) {
  const Vec3 normal = normalized(cross(triangle[1] - triangle[0], triangle[2] - triangle[0]));
  const Vec3 centre = (triangle[0] + triangle[1] + triangle[2]) / 3.0;
  double radius = 0;
  for (const Vec3& p : triangle) radius = std::max(radius, norm(p - centre));
  const double margin = 0.25 * options.width;
  const double slack = options.slack;
  if (normal == Vec3(0, 0, 0) || !(radius > margin) || !(options.cell > 0)) return std::nullopt;
  const double low = std::max(0.25 * options.width, 16 * slack);
  const double high = 2 * low;
  BoundingBox box;
  for (const Vec3& p : triangle) box.extend(p);
  std::vector<std::uint32_t> near;
  if (!nearby.for_each(box, std::max(2 * options.cutoff, high) + 2 * slack, options.max_cells,
                       [&](std::uint32_t t) { near.push_back(t); })) {
    return std::nullopt;
  }
  const double shrink = margin / radius;
  TriangleCorners shrunk;
  for (int k = 0; k < 3; ++k) shrunk[k] = centre + (1 - shrink) * (triangle[k] - centre);
  const std::span<const TriangleCorners> reference = nearby.triangles();

  TriangleCover cover;
  cover.slack_ = slack;
  if (options.side_is_continuous) {
    cover.side_ = free_prism_side(reference, near, shrunk, normal, low, high, witness, slack);
    cover.side_reached_ = -(low + margin * (1 + 1e-12) + 2 * slack);
  }

  // The triangles within the cutoff of the plane, with their greatest height.
  const auto height = [&](Vec3 p) { return dot(normal, p - triangle[0]); };
  std::vector<std::uint32_t> flat;
  std::vector<double> heights;
  for (const std::uint32_t t : near) {
    double h = 0;
    for (const Vec3& v : reference[t]) h = std::max(h, std::fabs(height(v)));
    if (h <= options.cutoff) {
      flat.push_back(t);
      heights.push_back(h);
    }
  }
  TriangleCorners in_plane;
  for (int k = 0; k < 3; ++k) in_plane[k] = shrunk[k] - height(shrunk[k]) * normal;
  if (flat.empty() || !shadows_cover(reference, flat, normal, in_plane, slack)) return cover;

  // The map over the triangle's shadow, grown by the rim, in cells of about a patch.
  cover.origin_ = triangle[0];
  cover.normal_ = normal;
  cover.e1_ = normalized(triangle[1] - triangle[0]);
  cover.e2_ = cross(normal, cover.e1_);
  double u_low = INFINITY, u_high = -INFINITY, v_low = INFINITY, v_high = -INFINITY;
  for (const Vec3& p : triangle) {
    const Vec3 r = p - triangle[0];
    u_low = std::min(u_low, dot(r, cover.e1_));
    u_high = std::max(u_high, dot(r, cover.e1_));
    v_low = std::min(v_low, dot(r, cover.e2_));
    v_high = std::max(v_high, dot(r, cover.e2_));
  }
  const double grow = margin * (1 + 1e-12) + 2 * slack;
  cover.u0_ = u_low - grow;
  cover.v0_ = v_low - grow;
  double cell = options.cell;
  const auto count = [&](double extent) {
    return static_cast<std::size_t>(std::floor((extent + 2 * grow) / cell)) + 1;
  };
  while (count(u_high - u_low) * count(v_high - v_low) > kMaxMapCells) cell *= 2;
  cover.cell_ = cell;
  cover.columns_ = count(u_high - u_low);
  cover.rows_ = count(v_high - v_low);
  cover.rim_ = shrink * radius * (1 + 1e-12);
  cover.highest_.assign(cover.columns_ * cover.rows_, -INFINITY);
  for (std::size_t k = 0; k < flat.size(); ++k) {
    double lu = INFINITY, hu = -INFINITY, lv = INFINITY, hv = -INFINITY;
    for (const Vec3& p : reference[flat[k]]) {
      const Vec3 r = p - triangle[0];
      lu = std::min(lu, dot(r, cover.e1_));
      hu = std::max(hu, dot(r, cover.e1_));
      lv = std::min(lv, dot(r, cover.e2_));
      hv = std::max(hv, dot(r, cover.e2_));
    }
    const auto first = [&](double x, double x0, std::size_t n) {
      return static_cast<std::size_t>(
          std::clamp(std::floor((x - slack - x0) / cell), 0.0, static_cast<double>(n - 1)));
    };
    if (hu + slack < cover.u0_ || hv + slack < cover.v0_) continue;
    const std::size_t i0 = first(lu, cover.u0_, cover.columns_);
    const std::size_t i1 = first(hu + 2 * slack, cover.u0_, cover.columns_);
    const std::size_t j0 = first(lv, cover.v0_, cover.rows_);
    const std::size_t j1 = first(hv + 2 * slack, cover.v0_, cover.rows_);
    for (std::size_t j = j0; j <= j1; ++j) {
      for (std::size_t i = i0; i <= i1; ++i) {
        double& h = cover.highest_[j * cover.columns_ + i];
        h = std::max(h, heights[k]);
      }
    }
  }
  cover.points_ = points_below(triangle, reference, flat, options);
  return cover;
}

void TriangleCover::bound(Patch& patch) const {
  const auto& c = patch.corners;
  if (side_ != 0 && patch.side == 0 &&
      std::none_of(c.begin(), c.end(),
                   [&](const PatchCorner& corner) { return side_ * corner.d < side_reached_; })) {
    patch.side = side_;
    patch.lower_abs = side_reached_;
  }
  if (highest_.empty()) return;
  // A point of the patch has, within the rim, a point of the shrunk triangle, straight above
  // or below which lies a covering triangle whose shadow meets the patch's grown by the rim.
  double patch_height = 0;
  double lu = INFINITY, hu = -INFINITY, lv = INFINITY, hv = -INFINITY;
  for (const PatchCorner& corner : c) {
    const Vec3 r = corner.point - origin_;
    patch_height = std::max(patch_height, std::fabs(dot(r, normal_)));
    lu = std::min(lu, dot(r, e1_));
    hu = std::max(hu, dot(r, e1_));
    lv = std::min(lv, dot(r, e2_));
    hv = std::max(hv, dot(r, e2_));
  }
  const double grow = rim_ + 2 * slack_;
  const auto cell_of = [&](double x, double x0, std::size_t n) {
    return static_cast<std::size_t>(
        std::clamp(std::floor((x - x0) / cell_), 0.0, static_cast<double>(n - 1)));
  };
  double highest = -INFINITY;
  for (std::size_t j = cell_of(lv - grow, v0_, rows_); j <= cell_of(hv + grow, v0_, rows_); ++j) {
    for (std::size_t i = cell_of(lu - grow, u0_, columns_); i <= cell_of(hu + grow, u0_, columns_);
         ++i) {
      highest = std::max(highest, highest_[j * columns_ + i]);
    }
  }
  // No covering triangle near: the patch lies in the rim only, where the map says nothing.
  if (!(highest >= 0)) return;
  patch.upper_abs = std::min(patch.upper_abs, patch_height + highest + rim_ + 2 * slack_);
}

}  // namespace ncv
