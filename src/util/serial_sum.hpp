// The sum of term(0) + term(1) + ... + term(n - 1) added in index order on one thread, the
// terms computed in parallel first: the serial loop's result to the bit whatever the threads,
// where a result is kept or compared bit for bit (a grid's cell size, a stored signed volume,
// the view's clustering) and a blocked reduction would round differently. For a million
// triangles the terms took 10-15 ms on one thread, the additions about 1 ms.
#pragma once

#include <cstddef>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "util/buffer.hpp"

namespace ncv {

template <class Term>
double serial_sum(std::size_t n, Term&& term) {
  Buffer<double> terms(n);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1 << 14), [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) terms[i] = term(i);
  });
  double sum = 0;
  for (const double t : terms) sum += t;
  return sum;
}

}  // namespace ncv
