// Shared by the libFuzzer targets. A target feeds its bytes to one reader exactly as
// ncverify does and then, when the reader accepts them, runs what ncverify runs next on
// the result, so a loader that lets something inconsistent through shows up as a crash
// downstream. The readers' documented failures, ncv::InputError and ncv::UsageError, are
// the expected outcome of bad bytes; anything else escaping (another exception, a crash, a
// sanitizer report, a timeout, running out of the -rss_limit_mb) is a bug.
#pragma once

#include <spdlog/spdlog.h>
#include <tbb/global_control.h>
#include <xxhash.h>

#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

#include "util/buffer.hpp"
#include "util/error.hpp"

namespace ncv::fuzz {

// Warnings about odd inputs are expected by the thousand; one worker thread keeps
// executions deterministic and the parallel code paths are the same code.
inline void quiet_and_serial() {
  spdlog::set_level(spdlog::level::off);
  static const auto one_thread =
      std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, 1);
}

// Runs `read`, swallowing only the two failures a bad input may cause.
template <class Read>
bool accepts(Read&& read) {
  try {
    read();
    return true;
  } catch (const InputError&) {
  } catch (const UsageError&) {
  }
  return false;
}

// The fuzz bytes as an ncverify container whose header length and content hash are made
// right. Random mutations almost never keep the XXH3 trailer valid, so without this the
// fuzzer would never get past the hash check into the metadata and section readers (the
// targets also try the bytes unchanged, which exercises the header checks themselves).
inline Buffer<char> sealed_container(const std::uint8_t* data, std::size_t size) {
  Buffer<char> bytes(data, data + size);
  if (bytes.size() < 72) return bytes;
  const std::uint64_t file_bytes = bytes.size();
  std::memcpy(bytes.data() + 24, &file_bytes, sizeof file_bytes);
  const std::uint64_t hash = XXH3_64bits(bytes.data(), bytes.size() - 8);
  std::memcpy(bytes.data() + bytes.size() - 8, &hash, sizeof hash);
  return bytes;
}

}  // namespace ncv::fuzz
