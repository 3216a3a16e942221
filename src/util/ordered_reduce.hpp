// Parallel reduction whose result does not depend on the thread count: the input is cut
// into blocks of a fixed size, each block is reduced on its own, and the block results
// are combined in block order. Floating-point sums are therefore bit-identical whether
// one thread or many ran them.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include <tbb/parallel_for.h>

namespace ncv {

// reduce_block(begin, end) returns the reduction of [begin, end); combine(acc, part)
// folds one block result into the accumulator.
template <class T, class ReduceBlock, class Combine>
T ordered_reduce(std::size_t count, std::size_t block_size, T identity, ReduceBlock&& reduce_block,
                 Combine&& combine) {
  const std::size_t blocks = (count + block_size - 1) / block_size;
  std::vector<T> parts(blocks, identity);
  tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
    parts[b] = reduce_block(b * block_size, std::min(count, (b + 1) * block_size));
  });
  T result = std::move(identity);
  for (const T& part : parts) combine(result, part);
  return result;
}

}  // namespace ncv
