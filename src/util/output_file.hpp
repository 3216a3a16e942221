// An output written atomically: data goes to a temporary file beside the target, which is
// renamed over the target only by commit(). A failed or interrupted run (exception,
// SIGINT, SIGTERM) removes the temporary file, so no truncated output is ever left for a
// Makefile to take as up to date. "-" writes standard output instead; device files and
// FIFOs (/dev/null, /dev/full, /dev/stdout) are written in place, never renamed over.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

namespace ncv {

enum class OutputKind { binary, text };

class OutputFile {
 public:
  // Binary output to a terminal is refused (UsageError).
  OutputFile(std::string path, OutputKind kind);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  void write(const void* data, std::size_t bytes);
  void write(std::string_view text) { write(text.data(), text.size()); }
  // Flushes, checks for write errors (disk full) and moves the file into place.
  void commit();

  const std::string& path() const { return path_; }
  std::string display_name() const;

 private:
  void fail(const std::string& problem);

  std::string path_;
  std::string temporary_path_;  // empty when writing in place
  std::FILE* file_ = nullptr;
  bool to_stdout_ = false;
  bool committed_ = false;
};

// Installs SIGINT/SIGTERM/SIGHUP handlers that remove every pending temporary output, then
// exit with 128 + signal, and a SIGBUS handler (a mapped input truncated by another
// program) that does the same after one error line, with exit status 2. Call once at
// start-up.
void install_output_cleanup_on_signals();

}  // namespace ncv
