#include "util/output_file.hpp"

#include <spdlog/spdlog.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>

#include "util/error.hpp"

namespace ncv {
namespace {

// Temporary paths the signal handler must remove: a fixed table of fixed buffers, because
// only async-signal-safe work (unlink, _exit) is allowed there. A slot is claimed, then
// filled, then published: the handler only ever reads a complete path.
constexpr std::size_t kMaxPending = 16;
constexpr std::size_t kMaxPathLength = 4096;
enum SlotState : int { kFree, kClaimed, kPublished };
std::array<std::array<char, kMaxPathLength>, kMaxPending> pending_paths{};
std::array<std::atomic<int>, kMaxPending> pending_state{};

void register_pending(const std::string& path) {
  if (path.size() >= kMaxPathLength) return;
  for (std::size_t slot = 0; slot < kMaxPending; ++slot) {
    int expected = kFree;
    if (pending_state[slot].compare_exchange_strong(expected, kClaimed)) {
      std::memcpy(pending_paths[slot].data(), path.c_str(), path.size() + 1);
      pending_state[slot] = kPublished;
      return;
    }
  }
}

void unregister_pending(const std::string& path) {
  for (std::size_t slot = 0; slot < kMaxPending; ++slot) {
    if (pending_state[slot] == kPublished && path == pending_paths[slot].data()) {
      pending_state[slot] = kFree;
    }
  }
}

void remove_pending() {
  for (std::size_t slot = 0; slot < kMaxPending; ++slot) {
    if (pending_state[slot] == kPublished) ::unlink(pending_paths[slot].data());
  }
}

// One line, so an interrupted job in a log says why it stopped and that it left nothing
// half-written; outputs a command had committed before stay (run's finished steps).
extern "C" void remove_pending_and_exit(int signal_number) {
  static constexpr char kMessage[] = "ncverify: interrupted; no partial output left\n";
  [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, kMessage, sizeof kMessage - 1);
  remove_pending();
  ::_exit(128 + signal_number);
}

// SIGBUS on x86-64 and AArch64 Linux means a mapped input file (input_bytes.hpp) lost pages
// under us: another program truncated it while it was being read. Bad input, not a crash.
extern "C" void report_truncated_input_and_exit(int) {
  static constexpr char kMessage[] =
      "ncverify: error: an input file was truncated while it was being read\n";
  [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, kMessage, sizeof kMessage - 1);
  remove_pending();
  ::_exit(2);
}

// Creates "PATH.tmp.PID.N", registered with the signal handler before it exists: a signal
// can then never find the file created but not yet registered (mkstemp, which names the
// file as it creates it, left that window open). Returns the descriptor, or -1 with errno.
int create_temporary(const std::string& path, std::string& temporary) {
  static std::atomic<unsigned> next{0};
  for (int attempt = 0; attempt < 100; ++attempt) {
    temporary = path + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(next++);
    register_pending(temporary);
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd >= 0) return fd;
    const int error = errno;
    unregister_pending(temporary);
    errno = error;
    if (error != EEXIST) break;
  }
  temporary.clear();
  return -1;
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
  std::signal(SIGBUS, report_truncated_input_and_exit);
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
  const int fd = create_temporary(path_, temporary_path_);
  if (fd < 0) fail(std::strerror(errno));
  ::fchmod(fd, 0644);
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
  std::error_code unknown;
  const std::uintmax_t bytes = std::filesystem::file_size(path_, unknown);
  spdlog::debug("wrote {} ({} bytes)", display_name(), unknown ? 0 : bytes);
}

}  // namespace ncv
