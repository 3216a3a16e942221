// Union-find over dense indices. The lower index of two roots becomes the root, so the
// partition and each set's representative are the same whatever order unions come in.
#pragma once

#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace ncv {

class DisjointSets {
 public:
  explicit DisjointSets(std::size_t count) : parent_(count) {
    std::iota(parent_.begin(), parent_.end(), std::uint64_t{0});
  }

  // Path halving keeps the trees shallow without recursion.
  std::uint64_t find(std::uint64_t x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }

  void unite(std::uint64_t a, std::uint64_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (b < a) std::swap(a, b);
    parent_[b] = a;
  }

 private:
  std::vector<std::uint64_t> parent_;
};

}  // namespace ncv
