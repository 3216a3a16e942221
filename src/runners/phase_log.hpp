// Wall time per phase of `run`; writing the intermediate files is a phase of its own
// ("write"), so the compute phases are what the algorithm costs. Logged at the end, and
// written with the peak memory as JSON for benchmarks (--timings).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "util/stopwatch.hpp"

namespace ncv {

class PhaseLog {
 public:
  // Ends the phase running since the last call (or since construction).
  void done(const std::string& phase);
  // Ends it as two phases: `first` took `first_seconds` of it (at most all), `second` the
  // rest (the distance step's search, then its certification).
  void done(const std::string& first, double first_seconds, const std::string& second);
  template <class Work>
  void time(const std::string& phase, Work&& work) {
    work();
    done(phase);
  }
  // "phases: read 0.1 s, ... total 0.5 s" on stderr; with a path, also the JSON: the phases,
  // their total, the peak memory and the figures in `extra`.
  void summary(const std::string& timings_path, nlohmann::json extra) const;

 private:
  void add(const std::string& phase, double seconds);

  Stopwatch clock_;
  std::vector<std::pair<std::string, double>> phases_;
};

}  // namespace ncv
