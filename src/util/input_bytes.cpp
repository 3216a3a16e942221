#include "util/input_bytes.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

#include "util/error.hpp"

namespace ncv {
namespace {

class FileDescriptor {
 public:
  explicit FileDescriptor(int fd, bool owned) : fd_(fd), owned_(owned) {}
  ~FileDescriptor() {
    if (owned_ && fd_ >= 0) ::close(fd_);
  }
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
  bool owned_;
};

// Everything left in fd, into a buffer. A regular file's size is known and real: one
// buffer of that size, plus a byte so that reaching the end needs no reallocation (each one
// copies everything read so far). Streams grow as data arrives and give back the excess
// at the end. The buffer is not zero-filled before read() fills it.
Buffer<char> read_all(int fd, const std::string& name, std::size_t expected) {
  Buffer<char> bytes(expected > 0 ? expected + 1 : std::size_t{1} << 16);
  std::size_t used = 0;
  for (;;) {
    if (used == bytes.size()) bytes.resize(2 * bytes.size());
    const ssize_t got = ::read(fd, bytes.data() + used, bytes.size() - used);
    if (got < 0) {
      if (errno == EINTR) continue;
      throw InputError(name, std::string("read error: ") + std::strerror(errno));
    }
    if (got == 0) break;
    used += static_cast<std::size_t>(got);
  }
  bytes.resize(used);
  if (expected == 0) bytes.shrink_to_fit();
  return bytes;
}

}  // namespace

std::string input_name(const std::string& path) {
  return path == "-" ? "standard input" : path;
}

InputBytes::InputBytes(Buffer<char> bytes) : owned_(std::move(bytes)) {}

InputBytes::~InputBytes() {
  unmap();
}

InputBytes::InputBytes(InputBytes&& other) noexcept
    : owned_(std::move(other.owned_)),
      mapping_(std::exchange(other.mapping_, nullptr)),
      mapped_bytes_(std::exchange(other.mapped_bytes_, 0)) {}

InputBytes& InputBytes::operator=(InputBytes&& other) noexcept {
  if (this == &other) return *this;
  unmap();
  owned_ = std::move(other.owned_);
  mapping_ = std::exchange(other.mapping_, nullptr);
  mapped_bytes_ = std::exchange(other.mapped_bytes_, 0);
  return *this;
}

void InputBytes::unmap() noexcept {
  if (mapping_) ::munmap(mapping_, mapped_bytes_);
  mapping_ = nullptr;
  mapped_bytes_ = 0;
}

InputBytes read_input_bytes(const std::string& path) {
  const std::string name = input_name(path);
  const bool from_stdin = path == "-";
  FileDescriptor fd(from_stdin ? STDIN_FILENO : ::open(path.c_str(), O_RDONLY | O_CLOEXEC),
                    !from_stdin);
  if (fd.get() < 0) throw InputError(name, std::strerror(errno));
  struct stat info {};
  if (::fstat(fd.get(), &info) != 0) throw InputError(name, std::strerror(errno));
  if (S_ISDIR(info.st_mode)) throw InputError(name, "is a directory, not a file");

  const bool regular = S_ISREG(info.st_mode);
  const auto file_size = static_cast<std::size_t>(regular ? info.st_size : 0);
  // Standard input is read even when it is a regular file: "-" may have been read from
  // already, and mapping would ignore the file position.
  if (regular && !from_stdin && file_size > 0) {
    void* mapping = ::mmap(nullptr, file_size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd.get(), 0);
    if (mapping != MAP_FAILED) return InputBytes(mapping, file_size);
    // Some file systems cannot be mapped; reading works everywhere.
  }
  return InputBytes(read_all(fd.get(), name, file_size));
}

}  // namespace ncv
