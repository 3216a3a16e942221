// Linear patches in a fixed order, read a range at a time: stored in an array, or made on
// demand (sampling/lattice_triangles.hpp). The statistics pass over a part's patches several
// times, each range in index order, so every sum they make is the same whichever source
// gives the patches.
#pragma once

#include <cstddef>
#include <span>

#include "geometry/linear_patch.hpp"

namespace ncv {

class PatchSource {
 public:
  virtual ~PatchSource() = default;

  virtual std::size_t size() const = 0;

  // Patches [begin, end): a view of stored ones, or `scratch` (at least end - begin long)
  // filled with them. Safe to call from several threads at once.
  virtual std::span<const LinearPatch> range(std::size_t begin, std::size_t end,
                                             std::span<LinearPatch> scratch) const = 0;
};

class StoredPatches final : public PatchSource {
 public:
  explicit StoredPatches(std::span<const LinearPatch> patches) : patches_(patches) {}

  std::size_t size() const override { return patches_.size(); }

  std::span<const LinearPatch> range(std::size_t begin, std::size_t end,
                                     std::span<LinearPatch>) const override {
    return patches_.subspan(begin, end - begin);
  }

 private:
  std::span<const LinearPatch> patches_;
};

}  // namespace ncv
