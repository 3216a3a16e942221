// ncverify: NC machining verification by exact signed distances (see README.md).
#include "app.hpp"
#include "util/output_file.hpp"

int main(int argc, char** argv) {
  ncv::install_output_cleanup_on_signals();
  return ncv::cmd::run_ncverify(argc, argv);
}
