#include "util/memory_guard.hpp"

#include <fmt/format.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <optional>
#include <string_view>

#include "util/error.hpp"

namespace ncv {

std::uint64_t physical_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page_size = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0) return std::uint64_t{8} << 30;
  return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page_size);
}

std::uint64_t peak_memory_bytes() {
  struct rusage usage {};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<std::uint64_t>(usage.ru_maxrss) * 1024;  // Linux reports kB
}

std::string format_bytes(std::uint64_t bytes) {
  const double value = static_cast<double>(bytes);
  if (value >= 1e9) return fmt::format("{:.1f} GB", value / 1e9);
  if (value >= 1e6) return fmt::format("{:.1f} MB", value / 1e6);
  if (value >= 1e3) return fmt::format("{:.1f} kB", value / 1e3);
  return fmt::format("{} B", bytes);
}

namespace {

// A positive whole number from the environment, else none.
std::optional<std::uint64_t> environment_count(const char* name) {
  const char* text = std::getenv(name);
  if (!text) return std::nullopt;
  std::uint64_t value = 0;
  const std::string_view view(text);
  const auto [end, error] = std::from_chars(view.data(), view.data() + view.size(), value);
  if (error != std::errc() || end != view.data() + view.size() || value == 0) return std::nullopt;
  return value;
}

}  // namespace

std::uint64_t memory_budget_bytes() {
  std::uint64_t budget = physical_memory_bytes() / 2;
  // A Slurm job started with --mem is killed beyond it (SLURM_MEM_PER_NODE, in MiB).
  if (const auto slurm = environment_count("SLURM_MEM_PER_NODE")) {
    budget = std::min(budget, (*slurm << 20) / 5 * 4);
  }
  if (const auto given = environment_count("NCV_MEMORY_BUDGET")) budget = std::min(budget, *given);
  return budget;
}

void check_memory_budget(const std::string& what, double bytes, bool force,
                         const std::string& way_out) {
  const std::uint64_t budget = memory_budget_bytes();
  if (force || bytes <= static_cast<double>(budget)) return;
  // The estimate can exceed 2^64 (a step of 1e-9 on a large part), where converting it to
  // an integer is undefined behaviour: it is written as a double.
  const std::string needed = bytes < 1e12 ? format_bytes(static_cast<std::uint64_t>(bytes))
                                          : fmt::format("{:.3g} GB", bytes / 1e9);
  throw UsageError(fmt::format("{} would need about {} of memory (the budget is {}); {}", what,
                               needed, format_bytes(budget), way_out));
}

}  // namespace ncv
