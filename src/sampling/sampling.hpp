// Lattice sampling of the workpiece (paper §3.1, docs/METHOD.md "Sampling").
//
// Triangle t with corners A, B, C and lattice size n holds the points
//   P(i,j) = A + i(B-A)/(n-1) + j(C-A)/(n-1),  0 <= i <= n-1,  0 <= j <= n-1-i.
// The three corners are mesh vertices and are shared: every sampled mesh vertex is one
// sample (vertex_sample), every other lattice point belongs to its triangle alone and is
// numbered consecutively from first_interior_sample[t] in row-major (i, then j) order.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "sampling/shard.hpp"
#include "util/buffer.hpp"
#include "util/enum_names.hpp"

namespace ncv {

enum class SamplingScheme : std::uint32_t {
  all = 1,       // paper scheme I: triangles with n < 2 contribute their three vertices
  paper_ii = 2,  // paper scheme II: triangles with n < 2 are not sampled
};

inline constexpr EnumName<SamplingScheme> kSamplingSchemeNames[] = {
    {SamplingScheme::all, "all"}, {SamplingScheme::paper_ii, "paper-ii"}};

inline constexpr std::uint32_t kNoSample = std::numeric_limits<std::uint32_t>::max();

// Memory a sample costs through the whole pipeline (samples, distances, reading copies): what
// the memory guard multiplies a sample count by before the samples are made.
inline constexpr double kBytesPerSampleDownstream = 160;

// Equation (1): n' = sqrt(1/4 + 2|T|/step^2) - 1/2, rounded to the nearest integer.
std::uint32_t lattice_size(double area, double step);
// Number of lattice points of a size-n lattice: n(n+1)/2.
constexpr std::uint64_t lattice_point_count(std::uint64_t n) {
  return n * (n + 1) / 2;
}
// Lattice points of a size-n lattice that are not corners (n >= 2).
constexpr std::uint64_t lattice_interior_count(std::uint64_t n) {
  return n < 2 ? 0 : lattice_point_count(n) - 3;
}

struct SampleSet {
  Mesh mesh;              // the sampled surface: the workpiece, or the nominal in reverse
  std::string source;     // the file it came from, for reports
  double step = 0;        // sampling step in model units
  std::string step_spec;  // as the user gave it ("0.1%" or "0.05")
  SamplingScheme scheme = SamplingScheme::all;
  std::uint64_t mesh_hash = 0;

  std::vector<std::uint32_t> lattice_sizes;  // lattice size per triangle; 0 = not sampled
  // Each triangle's area (triangle_area), from the plan: the statistics weigh every lattice
  // sub-triangle by it, and gathering three corners a triangle again cost them 15-18 % of
  // their time on a workpiece whose triangles come in random order (docs/PERFORMANCE.md).
  Buffer<double> triangle_areas;
  Buffer<std::uint64_t> first_interior_sample;  // first own (non-corner) sample of each triangle
  std::vector<std::uint32_t> vertex_sample;     // sample of each mesh vertex, or kNoSample

  // The samples this set holds are numbers first_sample .. first_sample + sample_count() - 1
  // of the lattice's total_samples: all of them, or a shard's range (shard.hpp).
  std::uint64_t total_samples = 0;
  std::uint64_t first_sample = 0;
  std::optional<Shard> shard;  // set when this is a shard's range

  // Per sample held, filled in parallel (Buffer: not zeroed first): its point, a triangle it
  // lies on (owner) and its lattice coordinates there.
  Buffer<Vec3> positions;
  Buffer<std::uint32_t> owner;
  Buffer<std::uint32_t> lattice_i;
  Buffer<std::uint32_t> lattice_j;

  std::size_t sample_count() const { return positions.size(); }
  bool whole() const { return first_sample == 0 && sample_count() == total_samples; }
  // Sample number of lattice point (i, j) of triangle t (t must be sampled).
  std::uint64_t sample_at(std::size_t t, std::uint32_t i, std::uint32_t j) const;
};

// Lattice point (i, j) of triangle t with lattice size n >= 2, computed as the sampler does:
// a corner is its mesh vertex, any other point A + i(B-A)/(n-1) + j(C-A)/(n-1).
struct LatticeFrame {
  LatticeFrame(const Mesh& mesh, std::size_t t, std::uint32_t n);
  Vec3 at(std::uint32_t i, std::uint32_t j) const {
    return a + static_cast<double>(i) * e1 + static_cast<double>(j) * e2;
  }
  Vec3 a, e1, e2;
};
Vec3 lattice_point(const Mesh& mesh, std::size_t t, std::uint32_t n, std::uint32_t i,
                   std::uint32_t j);

struct SamplingReport {
  std::uint64_t triangles = 0;
  std::uint64_t samples = 0;
  std::uint64_t small_triangles = 0;       // n' rounds below 2: vertices only (I) or skipped (II)
  std::uint64_t degenerate_triangles = 0;  // zero area
  double surface_area = 0;
};

// What sampling a mesh at a step gives, worked out before any sample exists: each
// triangle's lattice size (scheme I lifts n < 2 to 2, corners only; scheme II leaves such
// a triangle unsampled, 0) and the report's triangle counts. The memory guard reads the
// sample count from it; sample_mesh then builds on it rather than working it out again.
struct SamplingPlan {
  double step = 0;
  SamplingScheme scheme = SamplingScheme::all;
  std::vector<std::uint32_t> lattice_sizes;  // per triangle; 0 = not sampled
  Buffer<double> triangle_areas;             // per triangle, as triangle_area gives it
  SamplingReport counts;                     // small_triangles, degenerate_triangles, surface_area
};

SamplingPlan plan_sampling(const Mesh& mesh, double step, SamplingScheme scheme);

// Samples that sample_mesh would produce from the plan, computed without allocating them.
std::uint64_t predicted_sample_count(const Mesh& mesh, const SamplingPlan& plan);

// The plan must be plan_sampling(mesh, ...). With a shard, only its range of samples is made
// (the lattice bookkeeping is always the whole mesh's).
SampleSet sample_mesh(Mesh mesh, SamplingPlan plan, SamplingReport* report = nullptr,
                      const std::optional<Shard>& shard = std::nullopt);
// Plans and samples.
SampleSet sample_mesh(Mesh workpiece, double step, SamplingScheme scheme,
                      SamplingReport* report = nullptr);

}  // namespace ncv
