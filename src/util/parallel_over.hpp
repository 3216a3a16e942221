// body(i) for every i < count, in parallel, in ranges of at least `grain` indices: for loops
// whose iterations each write their own elements, so the result does not depend on the
// threads.
#pragma once

#include <cstddef>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace ncv {

template <class Body>
void parallel_over(std::size_t count, std::size_t grain, Body&& body) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, grain),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i) body(i);
                    });
}

}  // namespace ncv
