// InputBytes: a regular file mapped, anything else read, the same bytes either way.
#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <thread>

#include "scratch_dir.hpp"
#include "util/error.hpp"
#include "util/input_bytes.hpp"

using namespace ncv;
namespace fs = std::filesystem;

namespace {

std::string text_of(const InputBytes& bytes) {
  return {bytes.data(), bytes.size()};
}

// Every byte value, and more than a page, so that a mapping spans several pages.
std::string varied_content() {
  std::string content;
  for (int k = 0; k < 3 * 4096 + 17; ++k) content.push_back(static_cast<char>(k * 7 % 256));
  return content;
}

}  // namespace

TEST_CASE("a regular file is read whole, byte for byte") {
  const ScratchDir dir;
  const std::string content = varied_content();
  const InputBytes bytes = read_input_bytes(dir.file("varied.bin", content).string());
  CHECK(bytes.size() == content.size());
  CHECK(text_of(bytes) == content);
  CHECK(bytes.span().size() == content.size());
}

TEST_CASE("an empty file gives no bytes") {
  const ScratchDir dir;
  const InputBytes bytes = read_input_bytes(dir.file("empty.bin", "").string());
  CHECK(bytes.size() == 0);
}

TEST_CASE("a pipe is read to its end") {
  // A FIFO is not a regular file: it cannot be mapped and has no size ahead of its data.
  const ScratchDir dir;
  const fs::path fifo = dir.path() / "fifo";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const std::string content = varied_content() + varied_content();
  std::thread writer([&] { std::ofstream(fifo, std::ios::binary) << content; });
  const InputBytes bytes = read_input_bytes(fifo.string());
  writer.join();
  CHECK(text_of(bytes) == content);
}

TEST_CASE("a file the kernel reports as empty is still read to its end") {
  // /proc files are regular with st_size 0; a mapping of 0 bytes would lose their content.
  const InputBytes bytes = read_input_bytes("/proc/self/status");
  CHECK(text_of(bytes).find("Pid:") != std::string::npos);
}

TEST_CASE("bytes move with their owner, mapped or not") {
  const ScratchDir dir;
  const std::string content = varied_content();
  InputBytes mapped = read_input_bytes(dir.file("moved.bin", content).string());
  InputBytes moved = std::move(mapped);
  CHECK(mapped.size() == 0);  // a moved-from InputBytes is empty
  CHECK(text_of(moved) == content);

  Buffer<char> buffer(content.begin(), content.end());
  InputBytes owned(std::move(buffer));
  moved = std::move(owned);
  CHECK(text_of(moved) == content);
}

TEST_CASE("missing files and folders are input errors") {
  const ScratchDir dir;
  CHECK_THROWS_AS(read_input_bytes((dir.path() / "no-such-file").string()), InputError);
  CHECK_THROWS_AS(read_input_bytes(dir.path().string()), InputError);
}
