#include "input_bytes.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "error.hpp"

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

}  // namespace

std::string input_name(const std::string& path) {
  return path == "-" ? "standard input" : path;
}

Buffer<char> read_input_bytes(const std::string& path) {
  const std::string name = input_name(path);
  const bool from_stdin = path == "-";
  FileDescriptor fd(from_stdin ? STDIN_FILENO : ::open(path.c_str(), O_RDONLY | O_CLOEXEC),
                    !from_stdin);
  if (fd.get() < 0) throw InputError(name, std::strerror(errno));
  struct stat info {};
  if (::fstat(fd.get(), &info) != 0) throw InputError(name, std::strerror(errno));
  if (S_ISDIR(info.st_mode)) throw InputError(name, "is a directory, not a file");

  // A regular file's size is known and real: one buffer of that size, plus a byte so that
  // reaching the end needs no reallocation (each one copies everything read so far).
  // Streams grow as data arrives and give back the excess at the end.
  const bool sized = S_ISREG(info.st_mode);
  Buffer<char> bytes(sized ? static_cast<std::size_t>(info.st_size) + 1 : std::size_t{1} << 16);
  std::size_t used = 0;
  for (;;) {
    if (used == bytes.size()) bytes.resize(2 * bytes.size());
    const ssize_t got = ::read(fd.get(), bytes.data() + used, bytes.size() - used);
    if (got < 0) {
      if (errno == EINTR) continue;
      throw InputError(name, std::string("read error: ") + std::strerror(errno));
    }
    if (got == 0) break;
    used += static_cast<std::size_t>(got);
  }
  bytes.resize(used);
  if (!sized) bytes.shrink_to_fit();
  return bytes;
}

}  // namespace ncv
