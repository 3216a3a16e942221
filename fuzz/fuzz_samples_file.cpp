// Samples files (kind SMPL) as `distance` reads them: Container::parse, load_sample_set,
// then the per-sample normals the paper's sign rule computes from the loaded lattice.
#include "files/container.hpp"
#include "files/samples_file.hpp"
#include "fuzz_support.hpp"
#include "sampling/sample_normals.hpp"

namespace {

void read_samples(ncv::Buffer<char> bytes) {
  const ncv::Container c = ncv::Container::parse(
      std::move(bytes), "fuzz.samples", ncv::FileKind::samples, ncv::kSamplesFormatVersion);
  const ncv::SampleSet set = ncv::load_sample_set(c);
  const std::vector<ncv::Vec3> normals = ncv::sample_normals(set);
  if (normals.size() != set.sample_count()) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ncv::fuzz::quiet_and_serial();
  ncv::fuzz::accepts([&] { read_samples(ncv::Buffer<char>(data, data + size)); });
  ncv::fuzz::accepts([&] { read_samples(ncv::fuzz::sealed_container(data, size)); });
  return 0;
}
