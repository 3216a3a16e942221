#include "statistics/patch_passes.hpp"

#include "util/buffer.hpp"

namespace ncv {

// Per thread and kept: the worker threads live as long as the process, and a pass would
// otherwise map and clear a block's 2 MB again for every block.
std::span<LinearPatch> patch_scratch(std::size_t count) {
  thread_local Buffer<LinearPatch> scratch;
  if (scratch.size() < count) scratch.resize(count);
  return std::span(scratch).first(count);
}

}  // namespace ncv
