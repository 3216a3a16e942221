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
std::vector<Vec3> points_below(const TriangleCorners& triangle, MeshCorners reference,
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
    const TriangleCorners r = reference[t];
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
  const double slack = options.slack;
  const ContactPrism prism = contact_prism(options.width, slack);
  const ShrunkTriangle shrunk = shrink_towards_centre(triangle, prism.margin);
  if (normal == Vec3(0, 0, 0) || !(shrunk.radius > prism.margin) || !(options.cell > 0)) {
    return std::nullopt;
  }
  const BoundingBox box = BoundingBox::of(triangle);
  std::vector<std::uint32_t> near;
  if (!nearby.for_each(box, std::max(2 * options.cutoff, prism.high) + 2 * slack, options.max_cells,
                       [&](std::uint32_t t) {
                         near.push_back(t);
                         return true;
                       })) {
    return std::nullopt;
  }
  const MeshCorners reference = nearby.triangles();

  TriangleCover cover;
  cover.slack_ = slack;
  if (options.side_is_continuous) {
    cover.side_ = free_prism_side(reference, near, shrunk.corners, normal, prism.low, prism.high,
                                  witness, slack);
    cover.side_reached_ = prism.reached;
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
  for (int k = 0; k < 3; ++k) in_plane[k] = shrunk.corners[k] - height(shrunk.corners[k]) * normal;
  if (flat.empty() || !shadows_cover(reference, flat, normal, in_plane, slack)) return cover;

  // The map over the triangle's shadow, grown by the rim, in cells of about a patch.
  cover.origin_ = triangle[0];
  cover.normal_ = normal;
  cover.e1_ = normalized(triangle[1] - triangle[0]);
  cover.e2_ = cross(normal, cover.e1_);
  const Shadow whole = cover.shadow(triangle);
  const double grow = prism.margin * (1 + 1e-12) + 2 * slack;
  cover.u0_ = whole.u_low - grow;
  cover.v0_ = whole.v_low - grow;
  double cell = options.cell;
  const auto count = [&](double extent) {
    return static_cast<std::size_t>(std::floor((extent + 2 * grow) / cell)) + 1;
  };
  const double width_u = whole.u_high - whole.u_low, width_v = whole.v_high - whole.v_low;
  while (count(width_u) * count(width_v) > kMaxMapCells) cell *= 2;
  cover.cell_ = cell;
  cover.columns_ = count(width_u);
  cover.rows_ = count(width_v);
  cover.rim_ = shrunk.rim;
  cover.highest_.assign(cover.columns_ * cover.rows_, -INFINITY);
  for (std::size_t k = 0; k < flat.size(); ++k) {
    const Shadow s = cover.shadow(reference[flat[k]]);
    if (s.u_high + slack < cover.u0_ || s.v_high + slack < cover.v0_) continue;
    cover.raise(s, slack, heights[k]);
  }
  cover.points_ = points_below(triangle, reference, flat, options);
  return cover;
}

TriangleCover::Shadow TriangleCover::shadow(const TriangleCorners& points) const {
  Shadow s;
  for (const Vec3& p : points) {
    const Vec3 r = p - origin_;
    s.u_low = std::min(s.u_low, dot(r, e1_));
    s.u_high = std::max(s.u_high, dot(r, e1_));
    s.v_low = std::min(s.v_low, dot(r, e2_));
    s.v_high = std::max(s.v_high, dot(r, e2_));
  }
  return s;
}

TriangleCover::Cells TriangleCover::cells_under(const Shadow& s, double grow) const {
  const auto cell_of = [&](double x, double x0, std::size_t n) {
    return static_cast<std::size_t>(
        std::clamp(std::floor((x - x0) / cell_), 0.0, static_cast<double>(n - 1)));
  };
  return {cell_of(s.u_low - grow, u0_, columns_), cell_of(s.u_high + grow, u0_, columns_),
          cell_of(s.v_low - grow, v0_, rows_), cell_of(s.v_high + grow, v0_, rows_)};
}

void TriangleCover::raise(const Shadow& s, double grow, double height) {
  const Cells c = cells_under(s, grow);
  for (std::size_t j = c.j0; j <= c.j1; ++j) {
    for (std::size_t i = c.i0; i <= c.i1; ++i) {
      highest_[j * columns_ + i] = std::max(highest_[j * columns_ + i], height);
    }
  }
}

void TriangleCover::bound(Patch& patch) const {
  if (patch.side == 0) take_side(patch, side_, side_reached_);
  if (highest_.empty()) return;
  // A point of the patch has, within the rim, a point of the shrunk triangle, straight above
  // or below which lies a covering triangle whose shadow meets the patch's grown by the rim.
  double patch_height = 0;
  for (const PatchCorner& corner : patch.corners) {
    patch_height = std::max(patch_height, std::fabs(dot(corner.point - origin_, normal_)));
  }
  double highest = -INFINITY;
  const Cells c = cells_under(shadow(patch.points()), rim_ + 2 * slack_);
  for (std::size_t j = c.j0; j <= c.j1; ++j) {
    for (std::size_t i = c.i0; i <= c.i1; ++i)
      highest = std::max(highest, highest_[j * columns_ + i]);
  }
  // No covering triangle near: the patch lies in the rim only, where the map says nothing.
  if (!(highest >= 0)) return;
  patch.upper_abs = std::min(patch.upper_abs, patch_height + highest + rim_ + 2 * slack_);
}

}  // namespace ncv
