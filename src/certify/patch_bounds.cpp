#include "certify/patch_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>
#include <vector>

#include "geometry/prism_overlap.hpp"
#include "geometry/triangle_distance.hpp"

namespace ncv {
namespace {

// Cells a patch's surroundings may span before bound_by_nearby gives up on them: a patch that
// far from the reference has its side proven by the Lipschitz bound already, so only the
// lower bound on |d| would be lost, which the patch's splitting then provides.
constexpr std::uint64_t kMaxNearbyCells = 512;
// Triangles a covering may take: a patch over more is split first (its cost stays small).
constexpr std::size_t kMaxCoveringTriangles = 256;
// Triangles the side proof measures the patch against: a patch near more is split first,
// which costs three points, far less than measuring it against them all.
constexpr std::size_t kMaxSideCandidates = 48;
// Triangles the prism side proof tests: a patch near more is split first.
constexpr std::size_t kMaxPrismTriangles = 256;
// Nearby triangles tried one by one by convexity.
constexpr std::size_t kMaxSingleCandidates = 32;
// Reference triangles within this many rounding slacks of a plane count as lying in it: the
// float coordinates of a flat CAD face that is not axis-aligned stray that little from its
// plane; the bound grows by the actual deviation.
constexpr double kFlatTolerance = 1024;

int side_of(double d) {
  return d > 0 ? 1 : d < 0 ? -1 : 0;
}

// The corners' common side, or 0 when they differ or one lies on the surface.
int common_side(const Patch& patch) {
  const int s = side_of(patch.corners[0].d);
  for (const PatchCorner& c : patch.corners) {
    if (side_of(c.d) != s) return 0;
  }
  return s;
}

// Convexity with two triangles that share an edge and together make a convex, nearly flat
// quadrilateral (a CAD face split along its diagonal), for a patch across that diagonal: the
// second laid into the first's plane (its apex moved by eps, so every point of it by at most
// eps) makes with the first one convex planar set Q, whose distance is convex, so |d| <=
// dist(x, Q) + eps <= max over the corners of dist(c, Q) + eps (docs/CERTIFICATION.md).
std::optional<double> flat_pair_upper_abs(const Patch& patch, const TriangleCorners& a,
                                          const TriangleCorners& b) {
  int shared = 0, apex_a = -1, apex_b = -1;
  for (int i = 0; i < 3; ++i) {
    bool found = false;
    for (int k = 0; k < 3; ++k) found = found || a[i] == b[k];
    shared += found ? 1 : 0;
    if (!found) apex_a = i;
  }
  for (int k = 0; k < 3; ++k) {
    if (a[0] != b[k] && a[1] != b[k] && a[2] != b[k]) apex_b = k;
  }
  if (shared != 2 || apex_a < 0 || apex_b < 0) return std::nullopt;
  const Vec3 p = a[apex_a], q = a[(apex_a + 1) % 3], r = a[(apex_a + 2) % 3];
  const Vec3 n = normalized(cross(q - p, r - p));
  if (n == Vec3(0, 0, 0)) return std::nullopt;
  const double eps = std::fabs(dot(n, b[apex_b] - q));
  const Vec3 s = b[apex_b] - dot(n, b[apex_b] - q) * n;
  // Convex: the apexes on either side of the shared edge, the edge's ends on either side of
  // the line between the apexes (or on it).
  const bool apexes_apart = dot(n, cross(r - q, p - q)) * dot(n, cross(r - q, s - q)) < 0;
  const bool ends_apart = dot(n, cross(s - p, q - p)) * dot(n, cross(s - p, r - p)) <= 0;
  if (!apexes_apart || !ends_apart) return std::nullopt;
  const TriangleCorners laid = {q, r, s};
  double largest = 0;
  for (const PatchCorner& c : patch.corners) {
    largest =
        std::max(largest, std::min(closest_point_on_triangle(c.point, a).squared_distance,
                                   closest_point_on_triangle(c.point, laid).squared_distance));
  }
  return std::sqrt(largest) + eps;
}

// The pairs (i, k), i < k, of the triangles reference[near[.]] that share an edge (its two
// corners equal), which alone can make a flat pair: found by sorting their edges, not by
// trying every pair (up to 496 flat-pair tests a patch, 2 % of a finishing run's profile).
std::vector<std::pair<std::size_t, std::size_t>> edge_sharing_pairs(
    MeshCorners reference, std::span<const std::uint32_t> near) {
  struct Edge {
    std::array<double, 6> ends;
    std::size_t index;
  };
  std::vector<Edge> edges;
  for (std::size_t i = 0; i < near.size(); ++i) {
    const TriangleCorners t = reference[near[i]];
    for (int k = 0; k < 3; ++k) {
      Vec3 p = t[k], q = t[(k + 1) % 3];
      if (std::tie(q[0], q[1], q[2]) < std::tie(p[0], p[1], p[2])) std::swap(p, q);
      edges.push_back({{p[0], p[1], p[2], q[0], q[1], q[2]}, i});
    }
  }
  std::sort(edges.begin(), edges.end(), [](const Edge& x, const Edge& y) {
    return std::tie(x.ends, x.index) < std::tie(y.ends, y.index);
  });
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t a = 0; a < edges.size();) {
    std::size_t b = a;
    while (b < edges.size() && edges[b].ends == edges[a].ends) ++b;
    for (std::size_t i = a; i < b; ++i) {
      for (std::size_t k = i + 1; k < b; ++k) {
        if (edges[i].index != edges[k].index) pairs.emplace_back(edges[i].index, edges[k].index);
      }
    }
    a = b;
  }
  return pairs;
}

// Convexity: min over the corners' closest triangles t of max over corners of dist(c, t), and
// over the pairs of them that make a flat convex quadrilateral unless one triangle gives
// `enough` already.
double convex_upper_abs(const Patch& patch, MeshCorners reference, double enough) {
  const auto& c = patch.corners;
  if (c[0].face == c[1].face && c[1].face == c[2].face) {
    return std::max({std::fabs(c[0].d), std::fabs(c[1].d), std::fabs(c[2].d)});
  }
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    const std::uint32_t t = c[k].face;
    if ((k > 0 && t == c[0].face) || (k > 1 && t == c[1].face)) continue;  // seen
    const TriangleCorners triangle = reference[t];  // some other corner is measured against it
    double largest = 0;
    for (int m = 0; m < 3 && largest < best; ++m) {
      const double distance =
          c[m].face == t
              ? std::fabs(c[m].d)
              : std::sqrt(closest_point_on_triangle(c[m].point, triangle).squared_distance);
      largest = std::max(largest, distance);
    }
    best = std::min(best, largest);
  }
  // No bound goes below the corners' own |d|: a triangle that reaches it (or `enough`) leaves
  // a pair nothing to gain.
  if (best <= std::max({std::fabs(c[0].d), std::fabs(c[1].d), std::fabs(c[2].d), enough})) {
    return best;
  }
  for (int i = 0; i < 3; ++i) {
    for (int k = i + 1; k < 3; ++k) {
      if (c[i].face == c[k].face) continue;
      if (const std::optional<double> pair =
              flat_pair_upper_abs(patch, reference[c[i].face], reference[c[k].face])) {
        best = std::min(best, *pair);
      }
    }
  }
  return best;
}

// The covering radius of a triangle whose angle at `apex` is not acute, across from the edge
// pq (docs/CERTIFICATION.md "Bounds on one patch"): the farthest a point of it lies from every
// corner is where the perpendicular bisector of an edge at the apex meets pq, at
// |e apex|^2 |pq| / (2 (apex - e) . (f - e)) from that edge's end e (f the other end), which is
// at most half of pq. Half of pq where a product is too close to zero for its rounding.
double obtuse_covering_radius(Vec3 p, Vec3 q, Vec3 apex) {
  const double base = norm(q - p);
  const auto from_end = [&](Vec3 e, Vec3 f) {
    const double side = squared_norm(apex - e);
    if (side == 0) return 0.0;  // the apex on this end: the other end's bisector decides
    const double along = dot(apex - e, f - e);
    // Rounding leaves the product within 4 units in the last place of |apex - e| |pq|; above
    // a millionth of it, the quotient is within 1e-9 of its value.
    if (!(along > 1e-6 * std::sqrt(side) * base)) return std::numeric_limits<double>::infinity();
    return side * base / (2 * along);
  };
  const double farthest = std::max(from_end(p, q), from_end(q, p));
  return std::min(0.5 * base, farthest * (1 + 1e-8));
}

}  // namespace

double covering_radius(Vec3 a, Vec3 b, Vec3 c) {
  const double ab = squared_norm(b - a), bc = squared_norm(c - b), ca = squared_norm(a - c);
  const double longest = std::max({ab, bc, ca});
  // Acute: each squared edge is less than the sum of the other two.
  const bool acute = ab < bc + ca && bc < ca + ab && ca < ab + bc;
  const double twice_area = norm(cross(b - a, c - a));
  if (!acute || !(twice_area > 0)) {
    if (longest == ab) return obtuse_covering_radius(a, b, c);
    if (longest == bc) return obtuse_covering_radius(b, c, a);
    return obtuse_covering_radius(c, a, b);
  }
  const double circumradius = std::sqrt(ab * bc * ca) / (2 * twice_area);
  // Rounding can only make an almost-right triangle look acute; the circumradius is then
  // half its longest edge to within rounding, and the larger of the two is safe.
  return std::max(circumradius, 0.5 * std::sqrt(longest));
}

ShrunkTriangle shrink_towards_centre(const TriangleCorners& triangle, double margin) {
  const Vec3 centre = (triangle[0] + triangle[1] + triangle[2]) / 3.0;
  ShrunkTriangle shrunk;
  for (const Vec3& p : triangle) shrunk.radius = std::max(shrunk.radius, norm(p - centre));
  const double shrink = shrunk.radius > margin ? margin / shrunk.radius : 1.0;
  shrunk.rim = shrink * shrunk.radius * (1 + 1e-12);
  for (int k = 0; k < 3; ++k) shrunk.corners[k] = centre + (1 - shrink) * (triangle[k] - centre);
  return shrunk;
}

ContactPrism contact_prism(double width, double slack) {
  ContactPrism prism;
  prism.margin = 0.25 * width;
  prism.low = std::max(0.25 * width, 16 * slack);
  prism.high = 2 * prism.low;
  prism.reached = -(prism.low + prism.margin * (1 + 1e-12) + 2 * slack);
  return prism;
}

void take_side(Patch& patch, int side, double reached) {
  const auto& c = patch.corners;
  if (side == 0 || std::any_of(c.begin(), c.end(), [&](const PatchCorner& corner) {
        return side * corner.d < reached;
      })) {
    return;
  }
  patch.side = side;
  patch.lower_abs = reached;
}

void bound_from_corners(Patch& patch, MeshCorners reference, double slack, bool side_is_continuous,
                        const NearbyTargets* targets) {
  const auto& c = patch.corners;
  patch.side = 0;
  patch.lower_abs = 0;
  patch.high = std::numeric_limits<double>::infinity();
  patch.low = -patch.high;
  patch.radius = covering_radius(c[0].point, c[1].point, c[2].point);
  double h = 0;
  if (side_is_continuous) {
    h = patch.radius * (1 + 1e-12) + slack;
    patch.high = std::max({c[0].d, c[1].d, c[2].d}) + h;
    patch.low = std::min({c[0].d, c[1].d, c[2].d}) - h;
  }
  // The |d| that settles the sides the Lipschitz bounds leave open (0: no target known).
  double enough = 0;
  if (targets) {
    enough = std::numeric_limits<double>::infinity();
    if (patch.high > targets->upper) enough = targets->upper;
    if (patch.low < targets->lower) enough = std::min(enough, -targets->lower);
    enough -= slack;
  }
  patch.upper_abs = convex_upper_abs(patch, reference, enough) + slack;
  if (!side_is_continuous) return;
  const int side = common_side(patch);
  if (side == 0) return;
  const double least = std::min({std::fabs(c[0].d), std::fabs(c[1].d), std::fabs(c[2].d)});
  if (least > h) {
    patch.side = side;
    patch.lower_abs = least - h;
  }
}

namespace {

// Convexity with one reference triangle: |d| <= max over the corners of dist(c, t).
double farthest_corner_distance(const Patch& patch, const TriangleCorners& t) {
  double farthest = 0;
  for (const PatchCorner& c : patch.corners) {
    farthest = std::max(farthest, closest_point_on_triangle(c.point, t).squared_distance);
  }
  return std::sqrt(farthest);
}

// Whether the point lies inside triangle abc, all three in one plane with normal n, by more
// than rounding: each corner on the inner side of the opposite edge.
bool strictly_inside(Vec3 p, Vec3 a, Vec3 b, Vec3 c, Vec3 n) {
  const double s1 = dot(n, cross(b - a, p - a)), s2 = dot(n, cross(c - b, p - b)),
               s3 = dot(n, cross(a - c, p - c));
  return (s1 > 0 && s2 > 0 && s3 > 0) || (s1 < 0 && s2 < 0 && s3 < 0);
}

}  // namespace

bool shadows_cover(MeshCorners reference, std::span<const std::uint32_t> cover, Vec3 n,
                   const TriangleCorners& shrunk, double slack) {
  const Vec3 o = shrunk[0];
  const auto onto_plane = [&](Vec3 p) { return p - dot(n, p - o) * n; };
  const Vec3 middle = (shrunk[0] + shrunk[1] + shrunk[2]) / 3.0;
  BoundingBox shrunk_box;
  for (const Vec3& v : shrunk) shrunk_box.extend(v);
  // A point of the shrunk patch inside one of them: its centre, or one between the centre and a
  // corner when the centre lies on an edge (lattices and meshes often share their grid lines).
  const std::array<Vec3, 4> probes = {middle, 0.5 * (middle + shrunk[0]),
                                      0.5 * (middle + shrunk[1]), 0.5 * (middle + shrunk[2])};
  const bool some_inside = std::any_of(probes.begin(), probes.end(), [&](Vec3 probe) {
    return std::any_of(cover.begin(), cover.end(), [&](std::uint32_t t) {
      const TriangleCorners r = reference[t];
      return strictly_inside(probe, onto_plane(r[0]), onto_plane(r[1]), onto_plane(r[2]), n);
    });
  });
  if (!some_inside) return false;
  // Every edge by its end points in order, with the apex of its triangle.
  struct Edge {
    std::array<double, 6> ends;
    Vec3 apex;
  };
  // Only the edges whose shadow comes near the shrunk patch's matter, outline or not.
  std::vector<Edge> edges;
  for (const std::uint32_t t : cover) {
    const TriangleCorners corners = reference[t];
    for (int k = 0; k < 3; ++k) {
      Vec3 p = corners[k], q = corners[(k + 1) % 3];
      BoundingBox shadow;
      shadow.extend(onto_plane(p));
      shadow.extend(onto_plane(q));
      if (box_gap(shadow, shrunk_box) > slack) continue;
      if (std::tie(q[0], q[1], q[2]) < std::tie(p[0], p[1], p[2])) std::swap(p, q);
      edges.push_back({{p[0], p[1], p[2], q[0], q[1], q[2]}, corners[(k + 2) % 3]});
    }
  }
  std::sort(edges.begin(), edges.end(),
            [](const Edge& x, const Edge& y) { return x.ends < y.ends; });
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j].ends == edges[i].ends) ++j;
    const auto& e = edges[i].ends;
    const Vec3 p = onto_plane(Vec3(e[0], e[1], e[2])), q = onto_plane(Vec3(e[3], e[4], e[5]));
    bool inner = j - i == 2;
    if (inner) {
      const double side_a = dot(n, cross(q - p, onto_plane(edges[i].apex) - p));
      const double side_b = dot(n, cross(q - p, onto_plane(edges[i + 1].apex) - p));
      inner = side_a * side_b < 0;
    }
    if (!inner && !(triangle_distance_lower_bound({p, q, q}, shrunk, slack) > slack)) {
      return false;
    }
    i = j;
  }
  return true;
}

namespace {

// The reference triangles near a patch that lie within `cutoff` of its plane, seen from that
// plane, cover the patch (shrunk towards its centre by `margin`): then every point of the
// patch has a point of one of them straight above or below it, at most their greatest
// height away, plus the shrinking's rim (docs/CERTIFICATION.md "Covering triangles"). This
// bounds a patch over many small reference triangles: a flat face tessellated finely, the
// diagonal between two coplanar triangles, a scallop surface. The triangles cover the
// shrunk patch when a point of it lies inside one of them and no edge of their union's outline
// comes near it: an edge met by one of them only, by more than two, or by two that fold
// onto the same side; the shrunk patch, being connected, cannot leave the union without
// crossing the outline.
std::optional<double> covering_bound(const Patch& patch, NearbyTriangles& nearby, Vec3 n, Vec3 o,
                                     double cutoff, double margin, double slack) {
  const auto& c = patch.corners;
  if (n == Vec3(0, 0, 0)) return std::nullopt;
  const auto height = [&](Vec3 p) { return dot(n, p - o); };
  double patch_height = 0;
  for (const PatchCorner& corner : c)
    patch_height = std::max(patch_height, std::fabs(height(corner.point)));
  const auto onto_plane = [&](Vec3 p) { return p - height(p) * n; };
  const MeshCorners reference = nearby.triangles();
  // Gathered farther than the cutoff and the patch's height: an edge that is only on the
  // outline because its other triangle was not gathered lies farther than that from the
  // patch, so with both ends within the cutoff of the plane, its shadow stays clear of the
  // patch's.
  std::vector<std::uint32_t> cover;
  double highest = 0;
  if (!nearby.for_each(patch, 2 * cutoff + patch_height + slack, kMaxNearbyCells,
                       [&](std::uint32_t t) {
                         double h = 0;
                         for (const Vec3& v : reference[t]) h = std::max(h, std::fabs(height(v)));
                         if (h <= cutoff) {
                           cover.push_back(t);
                           highest = std::max(highest, h);
                         }
                         return cover.size() <= kMaxCoveringTriangles;
                       }) ||
      cover.empty() || cover.size() > kMaxCoveringTriangles) {
    return std::nullopt;
  }
  const ShrunkTriangle shrunk = shrink_towards_centre(patch.points(), margin);
  TriangleCorners in_plane;
  for (int k = 0; k < 3; ++k) in_plane[k] = onto_plane(shrunk.corners[k]);
  if (!shadows_cover(reference, cover, n, in_plane, slack)) return std::nullopt;
  return patch_height + highest + shrunk.rim;
}

// The least upper bound on |d| the triangles near the patch give: one triangle by
// convexity, or the triangles that cover it.
double nearby_upper_abs(const Patch& patch, NearbyTriangles& nearby, double width,
                        double enough_abs, double slack) {
  const MeshCorners reference = nearby.triangles();
  double largest = 0;
  for (const PatchCorner& c : patch.corners) largest = std::max(largest, std::fabs(c.d));
  // A triangle much farther than the corners from the surface would not bound |d| much below
  // their largest |d| anyway.
  const Vec3 a = patch.corners[0].point, b = patch.corners[1].point, c = patch.corners[2].point;
  const double reach = largest + 0.25 * covering_radius(a, b, c) + 8 * slack;
  double best = patch.upper_abs;
  std::vector<std::uint32_t> near;
  nearby.for_each(patch, reach, kMaxNearbyCells, [&](std::uint32_t t) {
    near.push_back(t);
    return near.size() <= kMaxSingleCandidates;
  });
  // Among many small triangles none is near all three corners: the covering below is for that.
  if (near.size() <= kMaxSingleCandidates) {
    for (const std::uint32_t t : near) {
      best = std::min(best, farthest_corner_distance(patch, reference[t]));
    }
    // And two by two: a CAD face split along its diagonal, the patch over both halves.
    for (const auto& [i, k] : edge_sharing_pairs(reference, near)) {
      if (best <= largest + width) break;
      if (const std::optional<double> pair =
              flat_pair_upper_abs(patch, reference[near[i]], reference[near[k]])) {
        best = std::min(best, *pair);
      }
    }
  }
  // Covering triangles as high as twice the corners' |d| (a scallop's crest between corners
  // in its troughs) and a little more, so that a patch on a face it coincides with is covered.
  // Seen from the patch's own plane (many small triangles under it), or from the plane of a
  // corner's closest triangle (a flat face it coincides with or hovers over).
  std::vector<std::pair<Vec3, Vec3>> planes = {{normalized(cross(b - a, c - a)), a}};
  std::vector<double> cutoffs = {2 * largest + width};
  for (int k = 0; k < 3; ++k) {
    const std::uint32_t face = patch.corners[k].face;
    if ((k > 0 && face == patch.corners[0].face) || (k > 1 && face == patch.corners[1].face)) {
      continue;
    }
    const TriangleCorners base = reference[face];
    const Vec3 normal = normalized(cross(base[1] - base[0], base[2] - base[0]));
    // A face parallel to one tried already gives the same covering.
    if (std::any_of(planes.begin(), planes.end(), [&](const std::pair<Vec3, Vec3>& plane) {
          return std::fabs(dot(plane.first, normal)) > 1 - 1e-12 &&
                 std::fabs(dot(plane.first, base[0] - plane.second)) <= kFlatTolerance * slack;
        })) {
      continue;
    }
    planes.push_back({normal, base[0]});
    cutoffs.push_back(kFlatTolerance * slack);
  }
  for (std::size_t k = 0; k < planes.size() && best > std::max(largest + width, enough_abs); ++k) {
    if (const std::optional<double> covered = covering_bound(
            patch, nearby, planes[k].first, planes[k].second, cutoffs[k], 0.25 * width, slack)) {
      best = std::min(best, *covered);
    }
  }
  return best;
}

}  // namespace

namespace {

// The side proof: the least distance between the patch and the reference triangles within
// upper_abs of it (none farther can be the nearest to a point of the patch).
void prove_side(Patch& patch, NearbyTriangles& nearby, double slack) {
  const int side = common_side(patch);
  if (side == 0) return;  // the corners already show that the error changes sign or is 0
  const TriangleCorners corners = {patch.corners[0].point, patch.corners[1].point,
                                   patch.corners[2].point};
  const MeshCorners reference = nearby.triangles();
  const double reach = patch.upper_abs;
  double least = reach;
  BoundingBox box;
  for (const Vec3& p : corners) box.extend(p);
  std::size_t measured = 0;
  const bool scanned = nearby.for_each(patch, reach, kMaxNearbyCells, [&](std::uint32_t t) {
    const TriangleCorners triangle = reference[t];
    if (box_gap(box, BoundingBox::of(triangle)) >= least) return true;
    ++measured;
    least = std::min(least, triangle_distance_lower_bound(corners, triangle, slack));
    return least > 0 && measured <= kMaxSideCandidates;
  });
  if (!scanned || measured > kMaxSideCandidates || !(least > 0)) return;
  patch.side = side;
  patch.lower_abs = std::max(patch.lower_abs, least);
}

}  // namespace

int free_prism_side(MeshCorners reference, std::span<const std::uint32_t> near,
                    const TriangleCorners& shrunk, Vec3 n, double low, double high,
                    const SideWitness& witness, double slack) {
  const Vec3 centre = (shrunk[0] + shrunk[1] + shrunk[2]) / 3.0;
  for (const double direction : {1.0, -1.0}) {
    const Prism prism{shrunk, direction * n, low, high};
    if (std::any_of(near.begin(), near.end(), [&](std::uint32_t t) {
          return triangle_meets_prism(reference[t], prism, slack);
        })) {
      continue;
    }
    return side_of(witness(centre + (direction * 0.5 * (low + high)) * n));
  }
  return 0;
}

namespace {

// The directions a contact prism may rise in: the patch's normal; for a patch of zero area
// (its corners on a line: a sliver a CAD export left), two directions across the line, as
// the proof below holds for a prism over any plane through the patch, and one of them may
// lie in a face the line runs along. None for a patch that is a point.
std::vector<Vec3> prism_normals(const Patch& patch) {
  const auto& c = patch.corners;
  const Vec3 normal = normalized(cross(c[1].point - c[0].point, c[2].point - c[0].point));
  if (normal != Vec3(0, 0, 0)) return {normal};
  Vec3 along(0, 0, 0);
  for (int k = 0; k < 3; ++k) {
    const Vec3 edge = c[(k + 1) % 3].point - c[k].point;
    if (squared_norm(edge) > squared_norm(along)) along = edge;
  }
  along = normalized(along);
  if (along == Vec3(0, 0, 0)) return {};
  // Across the line: from the coordinate axis least along it.
  int axis = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::fabs(along[k]) < std::fabs(along[axis])) axis = k;
  }
  Vec3 unit(0, 0, 0);
  unit[axis] = 1;
  const Vec3 first = normalized(cross(along, unit));
  return {first, normalized(cross(along, first))};
}

// The side proof where the patch touches the reference from one side (docs/CERTIFICATION.md
// "Contact"): a face machined exactly to the nominal, the line where it meets a face left
// higher. Over the patch shrunk by `margin`, a prism from height `low` to `high` on one side
// of its plane that no reference triangle meets holds no point of the surface, so all of it
// lies on one side, which one point of it, measured, tells. A point of the shrunk patch on
// the other side deeper than `low` would have a ball free of the surface reaching into the
// prism; the rim lost by shrinking adds `margin` by the Lipschitz property. So side * d >=
// -(low + margin) on the patch.
void prove_side_by_prism(Patch& patch, NearbyTriangles& nearby, const SideWitness& witness,
                         double width, double slack) {
  const ContactPrism prism = contact_prism(width, slack);
  const ShrunkTriangle shrunk = shrink_towards_centre(patch.points(), prism.margin);
  const std::vector<Vec3> normals = prism_normals(patch);
  if (normals.empty() || !(shrunk.radius > prism.margin)) return;
  std::vector<std::uint32_t> near;
  if (!nearby.for_each(patch, prism.high + 2 * slack, kMaxNearbyCells,
                       [&](std::uint32_t t) {
                         near.push_back(t);
                         return near.size() <= kMaxPrismTriangles;
                       }) ||
      near.size() > kMaxPrismTriangles) {
    return;
  }
  for (const Vec3& normal : normals) {
    const int side = free_prism_side(nearby.triangles(), near, shrunk.corners, normal, prism.low,
                                     prism.high, witness, slack);
    if (side != 0) {
      take_side(patch, side, prism.reached);
      return;
    }
  }
}

}  // namespace

void bound_by_nearby(Patch& patch, NearbyTriangles& nearby, const SideWitness& witness,
                     const NearbyTargets& targets, double slack, bool side_is_continuous) {
  patch.near_checked = true;
  // What |d| must not exceed for the patch to be settled: its upper bound below the upper
  // target, its lower bound above the lower one, whichever its side asks.
  const double for_upper = targets.upper, for_lower = -targets.lower;
  const double either_side = std::min(for_upper, for_lower);
  const auto lower_upper_abs = [&](double enough_abs) {
    patch.upper_abs = std::min(
        patch.upper_abs, nearby_upper_abs(patch, nearby, targets.width, enough_abs, slack) + slack);
  };
  // Corners well within what settles the patch on either side, none on the reference: |d|
  // bounded closely may settle it without its side, at less cost than the side proofs among
  // many nearby triangles (a coarse nominal patch over a finely tessellated workpiece). A
  // corner on the reference (a contact) asks for the prism's side proof first, which is
  // cheaper there.
  double largest = 0, least = INFINITY;
  for (const PatchCorner& c : patch.corners) {
    largest = std::max(largest, std::fabs(c.d));
    least = std::min(least, std::fabs(c.d));
  }
  const bool bounded_first = patch.side == 0 && largest <= 0.5 * either_side && least > slack;
  if (bounded_first) {
    lower_upper_abs(either_side);
    if (patch.upper_abs <= either_side) return;
  }
  if (side_is_continuous && patch.side == 0) prove_side(patch, nearby, slack);
  if (side_is_continuous && patch.side == 0) {
    prove_side_by_prism(patch, nearby, witness, targets.width, slack);
  }
  const double enough_abs = patch.side > 0 ? for_upper : patch.side < 0 ? for_lower : either_side;
  if (patch.upper_abs <= enough_abs || bounded_first) return;
  lower_upper_abs(enough_abs);
}

NearbyTriangles::NearbyTriangles(const SearchIndex& index)
    : index_(index), stamps_(index.triangles().size(), 0) {}

}  // namespace ncv
