#include "ncgen/placement.hpp"

#include <utility>

#include "ncgen/random.hpp"

namespace ncv::gen {

void shuffle_triangles(ncv::Mesh& mesh, std::uint64_t seed) {
  SplitMix64 random(seed);
  for (std::size_t k = mesh.triangles.size(); k > 1; --k) {
    // 64 random bits modulo k < 2^32: the bias is below 2^-32, far under what a test could see.
    const auto pick = static_cast<std::size_t>(random.next() % k);
    std::swap(mesh.triangles[k - 1], mesh.triangles[pick]);
  }
}

void shift(ncv::Mesh& mesh, const Vec3& offset) {
  for (Vec3& vertex : mesh.vertices) vertex += offset;
}

void place(ncv::Mesh& mesh, const Placement& placement) {
  if (placement.shuffle) shuffle_triangles(mesh, placement.seed);
  shift(mesh, placement.offset);
}

}  // namespace ncv::gen
