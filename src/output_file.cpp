#include "output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>

#include "error.hpp"

namespace ncv {
namespace {

// Temporary paths the signal handler must remove: a fixed table of fixed buffers, because
// only async-signal-safe work (unlink, _exit) is allowed there.
constexpr std::size_t kMaxPending = 16;
constexpr std::size_t kMaxPathLength = 4096;
std::array<std::array<char, kMaxPathLength>, kMaxPending> pending_paths{};
std::array<std::atomic<bool>, kMaxPending> pending_used{};

int register_pending(const std::string& path) {
  if (path.size() >= kMaxPathLength) return -1;
  for (std::size_t slot = 0; slot < kMaxPending; ++slot) {
    bool expected = false;
    if (pending_used[slot].compare_exchange_strong(expected, true)) {
      std::memcpy(pending_paths[slot].data(), path.c_str(), path.size() + 1);
      return static_cast<int>(slot);
    }
  }
  return -1;
}

void unregister_pending(const std::string& path) {
  for (std::size_t slot = 0; slot < kMaxPending; ++slot) {
    if (pending_used[slot] && path == pending_paths[slot].data()) pending_used[slot] = false;
  }
}

extern "C" void remove_pending_and_exit(int signal_number) {
  for (std::size_t slot = 0; slot < kMaxPending; ++slot) {
    if (pending_used[slot]) ::unlink(pending_paths[slot].data());
  }
  ::_exit(128 + signal_number);
}

bool is_special_file(const std::string& path) {
  struct stat info {};
  return ::stat(path.c_str(), &info) == 0 && !S_ISREG(info.st_mode);
}

}  // namespace

void install_output_cleanup_on_signals() {
  std::signal(SIGINT, remove_pending_and_exit);
  std::signal(SIGTERM, remove_pending_and_exit);
  std::signal(SIGHUP, remove_pending_and_exit);
}

OutputFile::OutputFile(std::string path, OutputKind kind) : path_(std::move(path)) {
  if (path_ == "-") {
    if (kind == OutputKind::binary && isatty(STDOUT_FILENO)) {
      throw UsageError(
          "refusing to write binary output to a terminal; redirect it or give -o FILE");
    }
    to_stdout_ = true;
    file_ = stdout;
    return;
  }
  if (is_special_file(path_)) {
    file_ = std::fopen(path_.c_str(), "wb");
    if (!file_) fail(std::strerror(errno));
    return;
  }
  temporary_path_ = path_ + ".tmp.XXXXXX";
  const int fd = ::mkstemp(temporary_path_.data());
  if (fd < 0) {
    const std::string problem = std::strerror(errno);
    temporary_path_.clear();
    fail(problem);
  }
  ::fchmod(fd, 0644);
  register_pending(temporary_path_);
  file_ = ::fdopen(fd, "wb");
  if (!file_) {
    ::close(fd);
    fail(std::strerror(errno));
  }
}

OutputFile::~OutputFile() {
  if (committed_) return;
  if (file_ && !to_stdout_) std::fclose(file_);
  if (!temporary_path_.empty()) {
    ::unlink(temporary_path_.c_str());
    unregister_pending(temporary_path_);
  }
}

std::string OutputFile::display_name() const {
  return to_stdout_ ? "standard output" : path_;
}

void OutputFile::fail(const std::string& problem) {
  throw InputError(display_name(), "cannot write: " + problem);
}

void OutputFile::write(const void* data, std::size_t bytes) {
  if (bytes == 0) return;
  if (std::fwrite(data, 1, bytes, file_) != bytes) fail(std::strerror(errno));
}

void OutputFile::commit() {
  if (std::fflush(file_) != 0 || std::ferror(file_)) fail(std::strerror(errno));
  committed_ = true;
  if (to_stdout_) return;
  const int closed = std::fclose(file_);
  file_ = nullptr;
  if (closed != 0) {
    committed_ = false;
    fail(std::strerror(errno));
  }
  if (temporary_path_.empty()) return;
  if (std::rename(temporary_path_.c_str(), path_.c_str()) != 0) {
    committed_ = false;
    fail(std::strerror(errno));
  }
  unregister_pending(temporary_path_);
}

}  // namespace ncv
