// Reading a whole input (a file, or standard input for "-") into memory.
#pragma once

#include <cstddef>
#include <span>
#include <string>

#include "util/buffer.hpp"

namespace ncv {

// The display name of an input path: "standard input" for "-".
std::string input_name(const std::string& path);

// A whole input's bytes, read-only. A regular file is mapped: its pages are the page
// cache's own, so reading the 140 MB distance file of the paper's finishing part costs no
// copy and no fresh memory for the kernel to zero (2 ms instead of 20-100 ms). Standard
// input, pipes, devices and files the kernel gives no size (/proc) are read into a buffer.
// Move-only.
//
// A mapped file that another program truncates while it is mapped would raise SIGBUS on
// the next access to the lost pages; install_output_cleanup_on_signals() turns that into
// one error line and exit status 2.
class InputBytes {
 public:
  InputBytes() = default;
  // Bytes already in memory (tests, fuzz targets); implicit, so that a buffer can be passed
  // wherever input bytes are expected.
  InputBytes(Buffer<char> bytes);
  ~InputBytes();
  InputBytes(InputBytes&& other) noexcept;
  InputBytes& operator=(InputBytes&& other) noexcept;
  InputBytes(const InputBytes&) = delete;
  InputBytes& operator=(const InputBytes&) = delete;

  const char* data() const { return mapping_ ? static_cast<const char*>(mapping_) : owned_.data(); }
  std::size_t size() const { return mapping_ ? mapped_bytes_ : owned_.size(); }
  std::span<const char> span() const { return {data(), size()}; }

 private:
  friend InputBytes read_input_bytes(const std::string& path);
  InputBytes(void* mapping, std::size_t bytes) : mapping_(mapping), mapped_bytes_(bytes) {}
  void unmap() noexcept;

  Buffer<char> owned_;       // the bytes, when they were read
  void* mapping_ = nullptr;  // the bytes, when the file is mapped
  std::size_t mapped_bytes_ = 0;
};

// Reads everything; memory grows only with the bytes actually present, so no header count
// can make it allocate more. Throws InputError (missing file, directory, read error).
InputBytes read_input_bytes(const std::string& path);

}  // namespace ncv
