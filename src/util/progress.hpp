// A progress bar on standard error, drawn only when stderr is a terminal and the log level
// shows info: pipes, CI and -q stay quiet.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace ncv {

class Progress {
 public:
  Progress(std::string label, std::uint64_t total);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // Called from one thread; redraws at most a few times a second.
  void update(std::uint64_t done);
  void finish();

 private:
  std::string label_;
  std::uint64_t total_;
  bool enabled_;
  bool finished_ = false;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace ncv
