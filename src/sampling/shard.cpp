#include "sampling/shard.hpp"

#include <fmt/format.h>

#include <charconv>

#include "util/error.hpp"

namespace ncv {
namespace {

std::uint64_t aligned_bound(std::uint64_t total, std::uint32_t k, std::uint32_t n) {
  if (k == n) return total;
  // floor(total * k / n) without overflow: (total % n) * k < n^2 fits easily.
  const std::uint64_t exact = total / n * k + total % n * k / n;
  return exact - exact % kShardAlignment;
}

}  // namespace

Shard Shard::parse(const std::string& text) {
  const std::size_t slash = text.find('/');
  std::uint32_t k = 0, n = 0;
  const auto read = [](std::string_view part, std::uint32_t& value) {
    const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
    return !part.empty() && error == std::errc() && end == part.data() + part.size();
  };
  if (slash == std::string::npos || !read(std::string_view(text).substr(0, slash), k) ||
      !read(std::string_view(text).substr(slash + 1), n)) {
    throw UsageError(fmt::format("shard '{}': write K/N, shard K of N (1/4 .. 4/4)", text));
  }
  if (n < 1 || n > kMaxShards || k < 1 || k > n) {
    throw UsageError(fmt::format("shard '{}': K must be 1 to N and N 1 to {}", text, kMaxShards));
  }
  return {k - 1, n};
}

std::string Shard::text() const {
  return fmt::format("{}/{}", index + 1, count);
}

SampleRange shard_range(std::uint64_t total_samples, const Shard& shard) {
  return {aligned_bound(total_samples, shard.index, shard.count),
          aligned_bound(total_samples, shard.index + 1, shard.count)};
}

}  // namespace ncv
