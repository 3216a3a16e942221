// ncverify: NC machining verification by exact signed distances (see README.md).
#include <malloc.h>

#include "app.hpp"
#include "util/output_file.hpp"

int main(int argc, char** argv) {
  // glibc's own limits once a large block has been freed, from the start: allocations up to
  // 32 MiB come from the heap, reused from phase to phase, instead of fresh pages each
  // (the large buffers are kept by util/buffer.cpp, so glibc no longer frees a large block to
  // raise them itself). Two-sided finishing run: 42 k -> 38 k page faults, peak memory
  // 544 -> 500 MiB, 10 pairs in turn wall 0.936x (docs/PERFORMANCE.md).
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 64 << 20);
  ncv::install_output_cleanup_on_signals();
  return ncv::cmd::run_ncverify(argc, argv);
}
