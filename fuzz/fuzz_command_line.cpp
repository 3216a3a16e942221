// The command line itself: random argument vectors, the arguments separated by newlines,
// run through exactly what main() runs (cmd/app.hpp) in a scratch folder that holds small
// bundled-style inputs of every kind (meshes, samples, grid and distance files, made at the
// start by the commands themselves). Every outcome must be an exit status ncverify
// documents: 0, 1 (out of tolerance), 2 (one error line) or 3 (not proven within tolerance);
// a crash, a sanitizer report, a timeout or an allocation beyond libFuzzer's limit is a bug.
//
// Kept out of the vectors: "--force" (it lifts the memory guard on purpose) and any '/', so
// that every path stays in the scratch folder, which is emptied of everything but the inputs
// after each run. Standard input is /dev/null and standard output is discarded. The memory
// budget is NCV_MEMORY_BUDGET = 16 MB (about 100,000 samples), so that the guard, not the
// machine or the timeout, stops a fine step.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "app.hpp"
#include "fuzz_support.hpp"

namespace {

int run(std::vector<std::string> args) {
  args.insert(args.begin(), "ncverify");
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  return ncv::cmd::run_ncverify(static_cast<int>(args.size()), argv.data());
}

// A box as binary STL, outward-oriented.
void write_box(const std::string& path, float x, float y, float z) {
  const float v[8][3] = {{0, 0, 0}, {x, 0, 0}, {x, y, 0}, {0, y, 0},
                         {0, 0, z}, {x, 0, z}, {x, y, z}, {0, y, z}};
  const int f[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                        {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  std::FILE* out = std::fopen(path.c_str(), "wb");
  char header[80] = {};
  std::fwrite(header, 1, 80, out);
  const std::uint32_t count = 12;
  std::fwrite(&count, 4, 1, out);
  for (const auto& t : f) {
    const float normal[3] = {0, 0, 0};
    std::fwrite(normal, 4, 3, out);
    for (int k = 0; k < 3; ++k) std::fwrite(v[t[k]], 4, 3, out);
    const std::uint16_t attribute = 0;
    std::fwrite(&attribute, 2, 1, out);
  }
  std::fclose(out);
}

const std::vector<std::string> kInputs = {"box.stl",  "low.stl",         "low.samples",
                                          "box.grid", "low.dist",        "box.samples",
                                          "low.grid", "box.reverse.dist"};

// Everything a run wrote into the scratch folder goes; the inputs stay.
void clean_up() {
  std::vector<std::filesystem::path> made;
  for (const auto& entry : std::filesystem::directory_iterator(".")) {
    const std::string name = entry.path().filename().string();
    if (std::find(kInputs.begin(), kInputs.end(), name) == kInputs.end()) made.push_back(entry);
  }
  for (const auto& path : made) std::filesystem::remove_all(path);
}

// The scratch folder, made with its inputs on the first call.
const std::filesystem::path& scratch() {
  static const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("ncverify-fuzz-cli-" + std::to_string(getpid()));
  return folder;
}

// In the scratch folder for one run; libFuzzer's own paths (corpus, artifacts) are relative
// to the folder it started in, so that is restored after.
class InScratch {
 public:
  InScratch() : home_(std::filesystem::current_path()) { std::filesystem::current_path(scratch()); }
  ~InScratch() { std::filesystem::current_path(home_); }
  InScratch(const InScratch&) = delete;
  InScratch& operator=(const InScratch&) = delete;

 private:
  std::filesystem::path home_;
};

void prepare() {
  static bool ready = false;
  if (ready) return;
  ready = true;
  std::filesystem::create_directories(scratch());
  const InScratch here;
  setenv("NCV_MEMORY_BUDGET", "16777216", 1);
  if (!std::freopen("/dev/null", "r", stdin) || !std::freopen("/dev/null", "w", stdout)) {
    std::abort();
  }
  write_box("box.stl", 10, 6, 4);
  write_box("low.stl", 10, 6, 3.8f);
  run({"-q", "sample", "low.stl", "-o", "low.samples", "--step", "2%"});
  run({"-q", "grid-build", "box.stl", "-o", "box.grid"});
  run({"-q", "distance", "low.samples", "box.grid", "-o", "low.dist"});
  run({"-q", "sample", "box.stl", "--step-from", "low.samples", "-o", "box.samples"});
  run({"-q", "grid-build", "low.stl", "-o", "low.grid"});
  run({"-q", "distance", "--reverse", "box.samples", "low.grid", "-o", "box.reverse.dist"});
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ncv::fuzz::quiet_and_serial();
  prepare();
  std::vector<std::string> args(1);
  for (std::size_t i = 0; i < size && args.size() <= 16; ++i) {
    if (data[i] == '\n') {
      args.emplace_back();
    } else {
      args.back() += static_cast<char>(data[i]);
    }
  }
  for (const std::string& arg : args) {
    if (arg.find('/') != std::string::npos || arg.find("--force") != std::string::npos) {
      return 0;
    }
  }
  const InScratch here;
  const int status = run(args);
  if (status != 0 && status != 1 && status != 2 && status != 3) __builtin_trap();
  clean_up();
  return 0;
}
