#include "certify/certify_surface.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "certify/patch_bounds.hpp"
#include "certify/triangle_cover.hpp"
#include "sampling/lattice_triangles.hpp"
#include "sampling/sample_normals.hpp"
#include "search/sample_searcher.hpp"
#include "util/buffer.hpp"
#include "util/ordered_reduce.hpp"

namespace ncv {
namespace {

// A backstop: every split at least halves a patch's area (split()); one still open at this
// depth is left open, counted as unresolved.
constexpr std::uint32_t kMaxDepth = 60;

// An acute patch is bisected when its halves' covering radii are at most this share of its
// own (bisected_edge). Points added, ncgen finishing / roughing forward: 33 k -> 21 k and
// 213 k -> 77 k (0.55-0.9 alike; 0.5 keeps fewer needles' bisections, 0.55 measured the same
// as 0.7, so no needle sits near the threshold); an equilateral patch (0.87) splits in four.
constexpr double kBisectedRadius = 0.7;

// A patch whose covering radius is within this many times the margin its corners leave to the
// target it misses is split before any nearby proof (splits_first). Certification of the
// decimated finishing job, forward + reverse: 4: 0.21 + 0.27 s, 8: 0.19 + 0.22, 16: 0.18 +
// 0.20, 32 the same, every patch: 0.18 + 0.18 but 3x the points added on the finishing job's
// reverse; the ncgen jobs the same from 4 to 32.
constexpr double kSplitFirstRadius = 16;
// Triangles per block of the lattice pass: a block starts with an empty fold, so its first
// triangles and each that raises the block's extremes have their covering radius worked out;
// larger blocks on a fine mesh do that less often (the 1.24 M-triangle finishing workpiece's
// certification with nothing to refine: 0.020-0.024 s with blocks of 1024, 0.019-0.021 s with
// 8192), and at least 128 blocks keep the cores busy on a coarse one. The result is the same
// for any blocks: the folds keep the earliest of equal bounds and are joined in order.
std::size_t triangles_per_block(std::size_t triangles) {
  return std::clamp<std::size_t>(triangles / 128, 1024, 8192);
}
// Open patches a sampled triangle must have before they are bounded once for all of them
// (TriangleCover): fewer cost less one by one.
constexpr std::size_t kLeastPatchesPerCover = 8;
// Open patches (by the cheap bounds, and not split first) a sampled triangle must have for its
// patches to be made with its TriangleCover at hand, and kept only if that leaves them open:
// a coarse triangle over a finer reference would otherwise hold all its patches open at once
// (the bundled box_scallop's nominal: 2.1 M patches, 0.96 GB). Patches that splitting settles
// do not count: a cover costs 1-20 ms to build over a decimated workpiece's slivers.
constexpr std::uint64_t kLeastPatchesDeferred = 256;
// Search grid cells the triangle's gathering may visit: a few per open patch, so that its
// cost stays that of the patches it bounds.
constexpr std::uint64_t kCoverCellsPerPatch = 64;
constexpr std::uint64_t kMaxNearbyCellsPerTriangle = 512;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The rounding slack of distances computed on coordinates of magnitude `scale`: the search's
// margin (closest_point_search.hpp), docs/CERTIFICATION.md "Rounding".
double rounding_slack(double scale) {
  return std::ldexp(scale, -30);
}

// The largest and the smallest of values offered with their places, the earlier one kept on
// a tie: the measured extremes, and the patches' bounds.
struct Extremes {
  double max = -kInfinity, min = kInfinity;
  Vec3 max_at{0, 0, 0}, min_at{0, 0, 0};

  void add(double high, Vec3 high_at, double low, Vec3 low_at) {
    if (high > max) {
      max = high;
      max_at = high_at;
    }
    if (low < min) {
      min = low;
      min_at = low_at;
    }
  }
  void add(double d, Vec3 at) { add(d, at, d, at); }
  void add(const Extremes& e) { add(e.max, e.max_at, e.min, e.min_at); }
};

// The patches' bounds folded (max: the largest upper bound, min: the smallest lower one).
struct BoundFold {
  Extremes bounds;
  std::uint64_t patches = 0, unresolved = 0;

  void add(const Patch& patch, bool open, Vec3 origin) {
    const Vec3 centre = patch.centre() + origin;
    bounds.add(patch.upper(), centre, patch.lower(), centre);
    unresolved += open ? 1 : 0;
  }
  void add(const BoundFold& f) {
    bounds.add(f.bounds);
    patches += f.patches;
    unresolved += f.unresolved;
  }
};

// A point's signed distance to the reference, as the distance step measures a sample.
class PointProbe {
 public:
  PointProbe(const SearchIndex& index, const SideRule& side) : search_(index), side_(side) {}
  PatchCorner measure(Vec3 local, Vec3 normal) {
    const ClosestHit hit = search_.closest(local, counters_);
    return {local, side_.signed_value(local, hit, normal), hit.triangle};
  }
  // The side witness of the prism proofs: the same measurement of a point off the surface
  // (the pseudonormal sign only, which needs no sample normal).
  SideWitness witness() {
    return [this](Vec3 p) { return measure(p, Vec3(0, 0, 0)).d; };
  }

 private:
  SampleSearcher search_;
  const SideRule& side_;
  SearchCounters counters_;
};

class Certifier {
 public:
  Certifier(const SampleSet& samples, const DistanceField& raw, const SearchIndex& index,
            const SideRule& side, const CertifyOptions& options)
      : samples_(samples),
        raw_(raw),
        index_(index),
        side_(side),
        width_(options.width.value_or(kDefaultCertifyWidth)),
        surface_(index.surface()),
        continuous_(side.method() == SignMethod::pseudonormal &&
                    index.surface().automatic_sign_method() == SignMethod::pseudonormal),
        whole_(samples.whole()),
        probes_([this] { return PointProbe(index_, side_); }),
        nearby_([this] { return NearbyTriangles(index_); }) {
    if (side.method() == SignMethod::paper) vertex_normals_ = vertex_normal_sums(samples.mesh);
    BoundingBox box = bounding_box(samples.mesh);
    const double scale =
        std::max({max_abs(surface_.to_local(box.min)), max_abs(surface_.to_local(box.max)),
                  max_abs(surface_.local_bounds().min), max_abs(surface_.local_bounds().max)});
    slack_ = rounding_slack(scale);
    cap_ = certify_points_cap(options, samples.total_samples);
  }

  Certificate run() {
    measure_missing_corners();
    measured_ = held_extremes();
    for (const auto& [sample, corner] : extra_) measured_.add(corner.d, global(corner.point));
    LatticePass lattice = bound_lattice();
    refine(bound_by_triangle(std::move(lattice.open), lattice.deferred));
    return certificate();
  }

 private:
  Vec3 global(Vec3 local) const { return local + surface_.origin(); }
  bool is_held(std::uint64_t s) const {
    return s >= samples_.first_sample && s - samples_.first_sample < samples_.sample_count();
  }
  // Whether bounds leave a patch open against measured extremes widened by the width asked.
  bool is_open(double upper, double lower, const Extremes& measured) const {
    return upper > measured.max + width_ || lower < measured.min - width_;
  }
  bool is_open(double upper, double lower) const { return is_open(upper, lower, measured_); }
  bool is_open(const Patch& p) const { return is_open(p.upper(), p.lower()); }
  // What settles a patch: the measured extremes widened by the width asked.
  NearbyTargets targets_of(const Extremes& measured) const {
    return {measured.max + width_, measured.min - width_, width_};
  }
  NearbyTargets targets_now() const { return targets_of(measured_); }

  // Whether this set holds sampled triangle t's anchor sample, and so bounds its patches. A
  // test per triangle where the passes meet it, not a list made first: listing the finishing
  // workpiece's 1.24 M triangles took 9-11 ms of a 31 ms certification with nothing to refine.
  bool covers(std::size_t t) const {
    const std::uint32_t n = samples_.lattice_sizes[t];
    if (n < 2) return false;
    if (whole_) return true;
    const std::uint64_t anchor = n >= 3 ? samples_.first_interior_sample[t]
                                        : samples_.vertex_sample[samples_.mesh.triangles[t][0]];
    return is_held(anchor);
  }

  Vec3 sample_normal(std::size_t t, std::uint32_t i, std::uint32_t j) const {
    const Mesh& mesh = samples_.mesh;
    const std::uint32_t n = samples_.lattice_sizes[t];
    if (vertex_normals_.empty()) return Vec3(0, 0, 0);
    if (i == 0 && j == 0) return normalized(vertex_normals_[mesh.triangles[t][0]]);
    if (i == n - 1 && j == 0) return normalized(vertex_normals_[mesh.triangles[t][1]]);
    if (i == 0 && j == n - 1) return normalized(vertex_normals_[mesh.triangles[t][2]]);
    return normal_of(static_cast<std::uint32_t>(t));
  }

  // Corners of covered triangles that another shard holds: measured again here.
  void measure_missing_corners() {
    if (samples_.whole()) return;
    struct Missing {
      std::uint64_t sample;
      std::uint32_t t, i, j;
    };
    std::vector<Missing> missing;
    for (std::uint32_t t = 0; t < samples_.mesh.triangle_count(); ++t) {
      if (!covers(t)) continue;
      const std::uint32_t n = samples_.lattice_sizes[t];
      for (std::uint32_t i = 0; i < n; ++i) {
        for (std::uint32_t j = 0; i + j < n; ++j) {
          const std::uint64_t s = samples_.sample_at(t, i, j);
          if (!is_held(s)) missing.push_back({s, t, i, j});
        }
      }
    }
    std::sort(missing.begin(), missing.end(),
              [](const Missing& a, const Missing& b) { return a.sample < b.sample; });
    missing.erase(
        std::unique(missing.begin(), missing.end(),
                    [](const Missing& a, const Missing& b) { return a.sample == b.sample; }),
        missing.end());
    extra_.resize(missing.size());
    tbb::parallel_for(std::size_t{0}, missing.size(), [&](std::size_t k) {
      const Missing& m = missing[k];
      const Vec3 p = lattice_point(samples_.mesh, m.t, samples_.lattice_sizes[m.t], m.i, m.j);
      extra_[k] = {m.sample,
                   probes_.local().measure(surface_.to_local(p), sample_normal(m.t, m.i, m.j))};
    });
  }

  PatchCorner corner(std::uint64_t s) const {
    if (is_held(s)) {
      const std::size_t k = s - samples_.first_sample;
      return {surface_.to_local(samples_.positions[k]), raw_.distance[k], raw_.closest_face[k]};
    }
    const auto it = std::lower_bound(extra_.begin(), extra_.end(), s,
                                     [](const std::pair<std::uint64_t, PatchCorner>& e,
                                        std::uint64_t v) { return e.first < v; });
    return it->second;
  }

  // The held samples' extremes, found by their values alone (the earlier sample on a tie, as
  // Extremes keeps it); only the two positions are read, not all 24 bytes a sample besides.
  Extremes held_extremes() const {
    const std::span<const double> d = raw_.distance;
    struct Places {
      std::size_t max = 0, min = 0;
    };
    if (d.empty()) return Extremes{};
    const Places places = ordered_reduce(
        d.size(), 1 << 16, Places{},
        [&](std::size_t begin, std::size_t end) {
          Places part{begin, begin};
          for (std::size_t k = begin + 1; k < end; ++k) {
            if (d[k] > d[part.max]) part.max = k;
            if (d[k] < d[part.min]) part.min = k;
          }
          return part;
        },
        [&](Places& into, const Places& part) {
          if (d[part.max] > d[into.max]) into.max = part.max;
          if (d[part.min] < d[into.min]) into.min = part.min;
        });
    Extremes e;
    e.add(d[places.max], samples_.positions[places.max], d[places.min],
          samples_.positions[places.min]);
    return e;
  }

  // A triangle whose patches are made with its cover: how many of them the cheap bounds leave
  // open and splitting would not settle first, and their corners' largest |d|.
  struct Deferred {
    std::uint32_t triangle = 0;
    std::uint64_t open = 0;
    double largest = 0;  // the open patches' corners' largest |d|
  };
  struct LatticePass {
    BoundFold fold;
    std::vector<Patch> open;
    std::vector<Deferred> deferred;
  };

  // A sample's signed distance and closest face, wherever it is held.
  std::pair<double, std::uint32_t> value(std::uint64_t s) const {
    if (is_held(s)) {
      const std::size_t k = s - samples_.first_sample;
      return {raw_.distance[k], raw_.closest_face[k]};
    }
    const PatchCorner c = corner(s);
    return {c.d, c.face};
  }
  // Its signed distance alone: what a whole triangle's bound reads for most of a surface, on
  // the path every sampled triangle takes (inlined there; value() was not).
  double distance_of(std::uint64_t s) const {
    return is_held(s) ? raw_.distance[s - samples_.first_sample] : corner(s).d;
  }

  struct CheapBounds {
    double largest = 0;        // the corners' largest |d|
    double high = 0, low = 0;  // the corners' largest and smallest d
    double upper_abs = 0, upper = 0, lower = 0;
  };
  // The cheap bounds of a lattice patch from its corners' values alone, without building it:
  // corners that share their closest triangle bound |d| by their largest |d| (convexity),
  // others by that plus the covering radius (Lipschitz); the covering radius scaled to the
  // lattice (sub-triangles are similar to their triangle) also bounds d itself, within it of
  // the corners' values, where the sign is the true side.
  // A patch these leave open is bounded again with the convexity bound over the corners'
  // closest triangles (bound_from_corners).
  CheapBounds bound_cheaply(std::uint64_t a, std::uint64_t b, std::uint64_t c, double cover) const {
    const auto [da, fa] = value(a);
    const auto [db, fb] = value(b);
    const auto [dc, fc] = value(c);
    const double largest = std::max({std::fabs(da), std::fabs(db), std::fabs(dc)});
    CheapBounds bounds;
    bounds.largest = largest;
    bounds.high = std::max({da, db, dc});
    bounds.low = std::min({da, db, dc});
    bounds.upper_abs = (fa == fb && fb == fc ? largest : largest + cover) + slack_;
    bounds.upper = bounds.upper_abs;
    bounds.lower = -bounds.upper_abs;
    if (continuous_) {
      bounds.upper = std::min(bounds.upper, bounds.high + cover);
      bounds.lower = std::max(bounds.lower, bounds.low - cover);
    }
    return bounds;
  }

  Vec3 global_centre(std::uint64_t a, std::uint64_t b, std::uint64_t c) const {
    return global((corner(a).point + corner(b).point + corner(c).point) / 3.0);
  }

  // A lattice triangle's samples' extremes: the largest and the smallest value. Its corners'
  // samples are its vertices'; the others follow one another from its first interior sample.
  std::pair<double, double> sample_extremes(std::uint32_t t) const {
    const Triangle& corners = samples_.mesh.triangles[t];
    const double a = distance_of(samples_.vertex_sample[corners[0]]);
    const double b = distance_of(samples_.vertex_sample[corners[1]]);
    const double c = distance_of(samples_.vertex_sample[corners[2]]);
    double high = std::max({a, b, c}), low = std::min({a, b, c});
    const std::uint64_t n = samples_.lattice_sizes[t];
    const std::uint64_t first = samples_.first_interior_sample[t];
    for (std::uint64_t s = first; s < first + n * (n + 1) / 2 - 3; ++s) {
      const double d = distance_of(s);
      high = std::max(high, d);
      low = std::min(low, d);
    }
    return {high, low};
  }

  // The largest cover with which whole_bounds stays within [lower, upper] for a triangle whose
  // samples' extremes are high and low (not positive when none does).
  double cover_within(double high, double low, double upper, double lower) const {
    if (continuous_) return std::min(upper - high, low - lower);
    const double largest = std::max(std::fabs(high), std::fabs(low));
    return std::min(upper - largest, -lower - largest);
  }

  // The bounds of a whole lattice triangle whose every point lies within `cover` of one of
  // its samples (Lipschitz), from the samples' extremes.
  std::pair<double, double> whole_bounds(double high, double low, double cover) const {
    const double largest = std::max(std::fabs(high), std::fabs(low)) + cover;
    return {continuous_ ? high + cover : largest, continuous_ ? low - cover : -largest};
  }

  // A whole lattice triangle settled by its samples' extremes, which most of a surface away
  // from its extremes is: its patches need no bounds of their own; they are counted, and the
  // triangle's bounds folded. `fits(c)` says whether its covering radius, scaled to the
  // lattice, is at most c (from the quick bound); `cover` gives it exactly, computed only when
  // the bounds may widen the fold (rarely). A patch's own bounds are never looser.
  template <class Fits, class Cover>
  void fold_whole(std::uint32_t t, double high, double low, Fits&& fits, Cover&& cover,
                  BoundFold& fold) const {
    const std::uint32_t n = samples_.lattice_sizes[t];
    fold.patches += std::uint64_t{n - 1} * (n - 1);
    if (fits(cover_within(high, low, fold.bounds.max, fold.bounds.min))) return;
    const auto [upper, lower] = whole_bounds(high, low, cover());
    if (upper > fold.bounds.max || lower < fold.bounds.min) {
      const Mesh& mesh = samples_.mesh;
      const Vec3 centre = (mesh.corner(t, 0) + mesh.corner(t, 1) + mesh.corner(t, 2)) / 3.0;
      fold.bounds.add(upper, centre, lower, centre);
    }
  }

  // A lattice patch bounded from its corners (and by its triangle's cover when it has one, which
  // is tried first, as it settles most of its triangle's patches): folded when that settles it
  // against the extremes `measured` (the measured ones, or more), else returned.
  std::optional<Patch> bound_patch(std::uint32_t t, std::uint64_t a, std::uint64_t b,
                                   std::uint64_t c, double radius, BoundFold& fold,
                                   const Extremes& measured,
                                   const TriangleCover* cover = nullptr) const {
    const auto open = [&](const Patch& p) { return is_open(p.upper(), p.lower(), measured); };
    ++fold.patches;
    const CheapBounds cheap = bound_cheaply(a, b, c, radius);
    if (!is_open(cheap.upper, cheap.lower, measured)) {
      // Where only rarely a new extreme: its place is worked out then.
      if (cheap.upper > fold.bounds.max || cheap.lower < fold.bounds.min) {
        const Vec3 centre = global_centre(a, b, c);
        fold.bounds.add(cheap.upper, centre, cheap.lower, centre);
      }
      return std::nullopt;
    }
    Patch patch;
    patch.corners = {corner(a), corner(b), corner(c)};
    patch.triangle = t;
    patch.upper_abs = cheap.upper_abs;
    patch.high = cheap.upper;
    patch.low = cheap.lower;
    if (cover) cover->bound(patch);
    if (open(patch)) {
      const NearbyTargets targets = targets_of(measured);
      bound_from_corners(patch, index_.triangles(), slack_, continuous_, &targets);
      patch.upper_abs = std::min(patch.upper_abs, cheap.upper_abs);
      if (cover) cover->bound(patch);
    }
    if (open(patch)) return patch;
    fold.add(patch, false, surface_.origin());
    return std::nullopt;
  }

  // How many of a triangle's patches the cheap bounds leave open and splitting would not settle
  // more cheaply (splits_first), and their corners' largest |d|.
  Deferred cheaply_open(std::uint32_t t, double cover) const {
    Deferred open{t};
    for_each_lattice_triangle(samples_, t, [&](std::uint64_t a, std::uint64_t b, std::uint64_t c) {
      const CheapBounds cheap = bound_cheaply(a, b, c, cover);
      if (!is_open(cheap.upper, cheap.lower) ||
          splits_first(cover, cheap.upper, cheap.lower, cheap.high, cheap.low)) {
        return;
      }
      ++open.open;
      open.largest = std::max(open.largest, cheap.largest);
    });
    return open;
  }

  // The covering radius of a triangle's lattice patches (similar to it, scaled by 1/(n-1)),
  // with the rounding slack.
  double lattice_cover(std::uint32_t t) const {
    const Mesh& mesh = samples_.mesh;
    const double steps = samples_.lattice_sizes[t] - 1;
    return covering_radius(mesh.corner(t, 0), mesh.corner(t, 1), mesh.corner(t, 2)) / steps *
               (1 + 1e-12) +
           slack_;
  }

  // Every lattice sub-triangle of the covered triangles bounded from its corners; the open
  // ones are returned, in lattice order, and the triangles with many left for their covers.
  LatticePass bound_lattice() {
    const Mesh& mesh = samples_.mesh;
    const NearbyTargets targets = targets_now();
    LatticePass pass = ordered_reduce(
        mesh.triangle_count(), triangles_per_block(mesh.triangle_count()), LatticePass{},
        [&](std::size_t begin, std::size_t end) {
          LatticePass part;
          for (std::uint32_t t = static_cast<std::uint32_t>(begin); t < end; ++t) {
            if (!covers(t)) continue;
            const double steps = samples_.lattice_sizes[t] - 1;
            const Vec3 p = mesh.corner(t, 0), q = mesh.corner(t, 1), r = mesh.corner(t, 2);
            const auto exact = [&] { return lattice_cover(t); };
            const auto [high, low] = sample_extremes(t);
            // The covering radius is at most the longest edge over sqrt(3) (the circumradius of
            // an acute triangle, whose largest angle is at least 60 degrees; at most half the
            // longest edge otherwise): tried first, squared (no root, no division on the way most
            // triangles take), with margins for the rounding: one slack beyond the one the
            // scaled radius carries, far above the few ulps the margin c itself may be off.
            const double longest_squared =
                std::max({squared_norm(q - p), squared_norm(r - q), squared_norm(p - r)});
            const auto fits = [&](double c) {
              const double reach = (c - 2 * slack_) * steps;
              return reach > 0 && longest_squared * (1 + 1e-9) <= 3 * reach * reach;
            };
            if (fits(cover_within(high, low, targets.upper, targets.lower))) {
              fold_whole(t, high, low, fits, exact, part.fold);
              continue;
            }
            const double cover = exact();
            const auto [whole_upper, whole_lower] = whole_bounds(high, low, cover);
            if (!is_open(whole_upper, whole_lower)) {
              fold_whole(
                  t, high, low, [&](double c) { return cover <= c; }, [&] { return cover; },
                  part.fold);
              continue;
            }
            if (lattice_triangle_count(samples_.lattice_sizes[t]) >= kLeastPatchesDeferred) {
              const Deferred open = cheaply_open(t, cover);
              if (open.open >= kLeastPatchesDeferred) {
                part.deferred.push_back(open);
                continue;
              }
            }
            for_each_lattice_triangle(
                samples_, t, [&](std::uint64_t a, std::uint64_t b, std::uint64_t c) {
                  if (std::optional<Patch> patch =
                          bound_patch(t, a, b, c, cover, part.fold, measured_)) {
                    part.open.push_back(*patch);
                  }
                });
          }
          return part;
        },
        [](LatticePass& into, const LatticePass& part) {
          into.fold.add(part.fold);
          into.open.insert(into.open.end(), part.open.begin(), part.open.end());
          into.deferred.insert(into.deferred.end(), part.deferred.begin(), part.deferred.end());
        });
    fold_ = pass.fold;
    pass.fold = BoundFold{};
    return pass;
  }

  // The normal a point of the sampled triangle is measured with (the paper's sign only).
  Vec3 normal_of(std::uint32_t t) const {
    return vertex_normals_.empty() ? Vec3(0, 0, 0) : normalized(area_vector(samples_.mesh, t));
  }

  // The cover of sampled triangle t for patches whose largest |d| at a corner is `largest`,
  // `open` of them to bound; nullopt when its surroundings are too large to gather.
  std::optional<TriangleCover> cover_of(std::uint32_t t, double largest, std::uint64_t open,
                                        std::uint64_t max_points) {
    const Mesh& mesh = samples_.mesh;
    const TriangleCorners corners = {surface_.to_local(mesh.corner(t, 0)),
                                     surface_.to_local(mesh.corner(t, 1)),
                                     surface_.to_local(mesh.corner(t, 2))};
    double longest = 0;
    for (int k = 0; k < 3; ++k)
      longest = std::max(longest, norm(corners[(k + 1) % 3] - corners[k]));
    TriangleCoverOptions options;
    options.cutoff = 2 * largest + width_;
    options.width = width_;
    options.cell = longest / (samples_.lattice_sizes[t] - 1);
    options.beyond = largest;
    options.max_points = max_points;
    options.max_cells = kMaxNearbyCellsPerTriangle + kCoverCellsPerPatch * open;
    options.side_is_continuous = continuous_;
    options.slack = slack_;
    return TriangleCover::build(corners, nearby_.local(), probes_.local().witness(), options);
  }

  // What a triangle's cover gave: the points it asks to measure, and for a deferred
  // triangle its patches' fold and those still open.
  struct Covered {
    std::vector<PatchCorner> measured;
    BoundFold fold;
    std::vector<Patch> open;
  };

  // The points a cover asks to measure, measured.
  std::vector<PatchCorner> measure_for(const TriangleCover& cover, std::uint32_t t) {
    std::vector<PatchCorner> measured;
    PointProbe& probe = probes_.local();
    for (const Vec3& p : cover.points_to_measure())
      measured.push_back(probe.measure(p, normal_of(t)));
    return measured;
  }

  // A deferred triangle's patches, each bounded from its corners and then by the triangle's
  // cover; those still open kept, in lattice order.
  Covered bound_deferred(const Deferred& deferred, std::uint64_t max_points) {
    const std::uint32_t t = deferred.triangle;
    const std::optional<TriangleCover> cover =
        cover_of(t, deferred.largest, deferred.open, max_points);
    const double radius = lattice_cover(t);
    // The points the cover asks for first: their values are measured extremes by the time the
    // patches are folded (bound_by_triangle), so a patch they settle is settled here, and
    // neither bounded further nor kept (the box nominal's scalloped faces: 650 k patches).
    Covered out;
    if (cover) out.measured = measure_for(*cover, t);
    Extremes against = measured_;
    for (const PatchCorner& m : out.measured) against.add(m.d, global(m.point));
    for_each_lattice_triangle(samples_, t, [&](std::uint64_t a, std::uint64_t b, std::uint64_t c) {
      if (std::optional<Patch> patch =
              bound_patch(t, a, b, c, radius, out.fold, against, cover ? &*cover : nullptr)) {
        out.open.push_back(*patch);
      }
    });
    return out;
  }

  // The open patches of a triangle with many: bounded by what the whole triangle proves
  // (TriangleCover) before each is bounded by its own nearby triangles, and the deferred
  // triangles' patches made with their covers; the still open ones are returned, in order.
  std::vector<Patch> bound_by_triangle(std::vector<Patch> open,
                                       const std::vector<Deferred>& deferred) {
    std::vector<std::pair<std::size_t, std::size_t>> runs;
    for (std::size_t i = 0; i < open.size();) {
      std::size_t j = i;
      std::size_t hard = 0;  // not settled more cheaply by splitting
      for (; j < open.size() && open[j].triangle == open[i].triangle; ++j) {
        hard += splits_first(open[j]) ? 0 : 1;
      }
      if (hard >= kLeastPatchesPerCover) runs.emplace_back(i, j);
      i = j;
    }
    const std::size_t covers = runs.size() + deferred.size();
    const std::uint64_t points_per_cover = covers == 0 ? 0 : (cap_ - added_) / covers;
    std::vector<Covered> covered(covers);
    tbb::parallel_for(std::size_t{0}, covers, [&](std::size_t r) {
      if (r >= runs.size()) {
        covered[r] = bound_deferred(deferred[r - runs.size()], points_per_cover);
        return;
      }
      const auto [begin, end] = runs[r];
      const std::uint32_t t = open[begin].triangle;
      double largest = 0;
      for (std::size_t k = begin; k < end; ++k) {
        for (const PatchCorner& c : open[k].corners) largest = std::max(largest, std::fabs(c.d));
      }
      const std::optional<TriangleCover> cover =
          cover_of(t, largest, end - begin, points_per_cover);
      if (!cover) return;
      for (std::size_t k = begin; k < end; ++k) cover->bound(open[k]);
      covered[r].measured = measure_for(*cover, t);
    });
    // The points measured, in order: the extremes they reach widen the targets.
    for (Covered& c : covered) {
      for (const PatchCorner& m : c.measured) measured_.add(m.d, global(m.point));
      added_ += c.measured.size();
      fold_.add(c.fold);
      open.insert(open.end(), c.open.begin(), c.open.end());
    }
    std::vector<Patch> still;
    for (const Patch& p : open) {
      if (is_open(p)) {
        still.push_back(p);
      } else {
        fold_.add(p, false, surface_.origin());
      }
    }
    return still;
  }

  // A patch open only because its Lipschitz bounds reach past the targets, which they would
  // not once it is split a few levels (its covering radius within kSplitFirstRadius times the
  // margin between its corners and the target it misses), is split before it is bounded by
  // its nearby triangles: a point measured costs about a microsecond, the nearby proofs
  // 10-100.
  bool splits_first(const Patch& p) const {
    if (p.near_checked) return false;
    const auto& c = p.corners;
    return splits_first(p.radius, p.upper(), p.lower(), std::max({c[0].d, c[1].d, c[2].d}),
                        std::min({c[0].d, c[1].d, c[2].d}));
  }
  // The same for a patch of covering radius h, bounds [lower, upper] and corners' values
  // within [low, high].
  bool splits_first(double h, double upper, double lower, double high, double low) const {
    if (!continuous_) return false;
    const NearbyTargets targets = targets_now();
    double margin = kInfinity;
    if (upper > targets.upper) margin = targets.upper - high;
    if (lower < targets.lower) margin = std::min(margin, low - targets.lower);
    return margin > 0 && h <= kSplitFirstRadius * margin;
  }

  // How far a patch's bounds lie beyond the measured extremes and the width asked.
  double excess(const Patch& p) const {
    return std::max(p.upper() - (measured_.max + width_), (measured_.min - width_) - p.lower());
  }

  // Round by round: bound the open patches by their nearby triangles, then split the worst
  // quarter of those still open (the worst first while the cap lasts, so that the points go
  // where the bounds are loosest), measure the new midpoints, and keep the children and the
  // patches not split yet that are still open. Each round's choice depends on the values
  // only, never on the threads.
  void refine(std::vector<Patch> open) {
    while (!open.empty()) {
      const NearbyTargets targets = targets_now();
      tbb::parallel_for(std::size_t{0}, open.size(), [&](std::size_t k) {
        if (!open[k].near_checked && !splits_first(open[k])) {
          PointProbe& probe = probes_.local();
          const SideWitness witness = probe.witness();
          bound_by_nearby(open[k], nearby_.local(), witness, targets, slack_, continuous_);
        }
      });
      std::vector<Patch> waiting;
      for (const Patch& p : open) {
        if (is_open(p) && p.depth < kMaxDepth) {
          waiting.push_back(p);
        } else {
          fold_.add(p, is_open(p), surface_.origin());
        }
      }
      const std::uint64_t budget = (cap_ - added_) / 3;
      if (waiting.empty() || budget == 0) {
        for (const Patch& p : waiting) fold_.add(p, true, surface_.origin());
        return;
      }
      // Those split first, then the worst of the others.
      const auto first_rest = std::stable_partition(
          waiting.begin(), waiting.end(), [&](const Patch& p) { return splits_first(p); });
      const auto first = static_cast<std::size_t>(first_rest - waiting.begin());
      std::stable_sort(first_rest, waiting.end(),
                       [&](const Patch& x, const Patch& y) { return excess(x) > excess(y); });
      const std::size_t rest = waiting.size() - first;
      const std::size_t take = static_cast<std::size_t>(std::min<std::uint64_t>(
          budget, first + (rest > 0 ? std::max<std::size_t>(rest / 4, 1) : 0)));
      const Buffer<Patch> children = split(std::span<const Patch>(waiting).first(take));
      splits_ += take;
      open.assign(waiting.begin() + static_cast<std::ptrdiff_t>(take), waiting.end());
      for (const Patch& child : children) {
        if (is_open(child)) {
          open.push_back(child);
        } else {
          fold_.add(child, false, surface_.origin());
        }
      }
    }
  }

  // How a patch is split: in two at the middle of its longest edge when it is obtuse (its
  // covering radius at most half that edge, the halves' at most half of that or of their
  // other edges), or when that alone brings the covering radius to kBisectedRadius of its own
  // (a needle's, to about half, as four would), for one point measured; else into four at its
  // edge midpoints (three points). Returns the longest edge's first corner for a bisection, -1
  // for four.
  static int bisected_edge(const Patch& p) {
    const auto& c = p.corners;
    std::array<double, 3> squared{};
    for (int k = 0; k < 3; ++k) squared[k] = squared_norm(c[(k + 1) % 3].point - c[k].point);
    const int e =
        static_cast<int>(std::max_element(squared.begin(), squared.end()) - squared.begin());
    if (squared[e] > squared[(e + 1) % 3] + squared[(e + 2) % 3]) return e;
    const Vec3 from = c[e].point, to = c[(e + 1) % 3].point, apex = c[(e + 2) % 3].point;
    const Vec3 middle = 0.5 * (from + to);
    const double halves =
        std::max(covering_radius(from, middle, apex), covering_radius(middle, to, apex));
    return halves <= kBisectedRadius * p.radius ? e : -1;
  }

  // Each patch split (bisected_edge); the new points measured, added to the measured extremes
  // in order. Returns the children, in order, and counts the points in added_. In a Buffer:
  // a round's children (tens of MB) were fresh pages each round, cleared by the kernel.
  Buffer<Patch> split(std::span<const Patch> parents) {
    std::vector<int> edges(parents.size());
    std::vector<std::size_t> first(parents.size() + 1, 0);
    for (std::size_t k = 0; k < parents.size(); ++k) {
      edges[k] = bisected_edge(parents[k]);
      first[k + 1] = first[k] + (edges[k] >= 0 ? 2 : 4);
    }
    Buffer<Patch> children(first.back());
    std::vector<std::array<PatchCorner, 3>> points(parents.size());  // the new ones, per parent
    const auto reference = index_.triangles();
    const NearbyTargets targets = targets_now();
    tbb::parallel_for(std::size_t{0}, parents.size(), [&](std::size_t k) {
      const Patch& p = parents[k];
      const Vec3 normal = normal_of(p.triangle);
      PointProbe& probe = probes_.local();
      const auto& c = p.corners;
      const auto middle = [&](int i) {
        return probe.measure(0.5 * (c[i].point + c[(i + 1) % 3].point), normal);
      };
      std::array<std::array<PatchCorner, 3>, 4> parts;
      if (const int e = edges[k]; e >= 0) {
        const PatchCorner m = middle(e);
        const PatchCorner &from = c[e], &to = c[(e + 1) % 3], &apex = c[(e + 2) % 3];
        parts[0] = {from, m, apex};
        parts[1] = {m, to, apex};
        points[k][0] = m;
      } else {
        const PatchCorner ab = middle(0), bc = middle(1), ca = middle(2);
        parts = {{{c[0], ab, ca}, {ab, c[1], bc}, {ca, bc, c[2]}, {ab, bc, ca}}};
        points[k] = {ab, bc, ca};
      }
      for (std::size_t q = 0; q < first[k + 1] - first[k]; ++q) {
        Patch& child = children[first[k] + q];
        child = Patch{};
        child.corners = parts[q];
        child.triangle = p.triangle;
        child.depth = p.depth + 1;
        bound_from_corners(child, reference, slack_, continuous_, &targets);
      }
    });
    for (std::size_t k = 0; k < parents.size(); ++k) {
      const std::size_t count = edges[k] >= 0 ? 1 : 3;
      for (std::size_t i = 0; i < count; ++i) {
        measured_.add(points[k][i].d, global(points[k][i].point));
      }
      added_ += count;
    }
    return children;
  }

  Certificate certificate() const {
    Certificate c;
    c.width_asked = width_;
    c.points_cap = cap_;
    const Extremes& b = fold_.bounds;
    c.max = {measured_.max, measured_.max_at, std::max(b.max, measured_.max),
             b.max > measured_.max ? b.max_at : measured_.max_at};
    c.min = {measured_.min, measured_.min_at, std::min(b.min, measured_.min),
             b.min < measured_.min ? b.min_at : measured_.min_at};
    c.patches = fold_.patches;
    c.refined_patches = splits_;
    c.added_points = added_;
    c.unresolved = fold_.unresolved;
    c.sign_proven = continuous_;
    c.first_anchor = samples_.first_sample;
    c.end_anchor = samples_.first_sample + samples_.sample_count();
    return c;
  }

  const SampleSet& samples_;
  const DistanceField& raw_;
  const SearchIndex& index_;
  const SideRule& side_;
  const double width_;
  const ReferenceSurface& surface_;
  const bool continuous_;
  const bool whole_;  // every triangle's anchor held: none to look up
  tbb::enumerable_thread_specific<PointProbe> probes_;
  tbb::enumerable_thread_specific<NearbyTriangles> nearby_;
  std::vector<Vec3> vertex_normals_;
  double slack_ = 0;
  std::uint64_t cap_ = 0;
  std::vector<std::pair<std::uint64_t, PatchCorner>> extra_;
  Extremes measured_;
  BoundFold fold_;
  std::uint64_t splits_ = 0, added_ = 0;
};

}  // namespace

std::uint64_t certify_points_cap(const CertifyOptions& options, std::uint64_t total_samples) {
  return options.points_cap ? options.points_cap
                            : std::max<std::uint64_t>(kLeastPointsCap, total_samples);
}

Certificate certify_surface(const SampleSet& samples, const DistanceField& raw,
                            const SearchIndex& index, const SideRule& side,
                            const CertifyOptions& options) {
  return Certifier(samples, raw, index, side, options).run();
}

}  // namespace ncv
