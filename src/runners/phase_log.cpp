#include "runners/phase_log.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "util/memory_guard.hpp"
#include "util/output_file.hpp"

namespace ncv {

void PhaseLog::done(const std::string& phase) {
  const double seconds = clock_.seconds();
  clock_.restart();
  add(phase, seconds);
}

void PhaseLog::done(const std::string& first, double first_seconds, const std::string& second) {
  const double seconds = clock_.seconds();
  clock_.restart();
  const double part = std::min(first_seconds, seconds);
  add(first, part);
  add(second, seconds - part);
}

void PhaseLog::add(const std::string& phase, double seconds) {
  for (auto& [name, total] : phases_) {
    if (name == phase) {
      total += seconds;
      return;
    }
  }
  phases_.push_back({phase, seconds});
}

void PhaseLog::summary(const std::string& timings_path, nlohmann::json extra) const {
  std::string line;
  double total = 0;
  nlohmann::json phases = nlohmann::json::object();
  for (const auto& [phase, seconds] : phases_) {
    line += fmt::format("{} {:.3f} s, ", phase, seconds);
    phases[phase] = seconds;
    total += seconds;
  }
  spdlog::info("phases: {}total {:.3f} s", line, total);
  if (timings_path.empty()) return;
  nlohmann::json timings = {{"phases", phases}, {"total", total}};
  timings.update(extra);
  timings["peak_memory_bytes"] = peak_memory_bytes();
  OutputFile out(timings_path, OutputKind::text);
  out.write(timings.dump(2) + "\n");
  out.commit();
}

}  // namespace ncv
