// run's output folder, made only once the inputs are read and every output path is known to
// be writable; if the run then fails, what it wrote goes again, and the folders it made, so a
// failed run leaves nothing behind (an interrupt keeps the steps already finished:
// util/output_file.hpp).
#pragma once

#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include "util/output_file.hpp"

namespace ncv {

// Throws InputError ("cannot write: ...") unless a file could be created at `path`: its
// folder exists and is writable. "-" (standard output) always can.
void check_writable(const std::string& path);

class RunFolder {
 public:
  // Checks that `path` is a folder or can be made one; nothing is created yet.
  explicit RunFolder(std::filesystem::path path);
  RunFolder(const RunFolder&) = delete;
  RunFolder& operator=(const RunFolder&) = delete;
  ~RunFolder();  // discards what was written unless keep() was called

  // Makes the folder (and missing parents) when first needed.
  void create();
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

  // Writes a file (in the folder or anywhere) atomically and remembers it.
  template <class Write>
  void write(const std::filesystem::path& file, OutputKind kind, Write&& write_content) {
    create();
    OutputFile out(file.string(), kind);
    write_content(out);
    out.commit();
    written(file);
  }
  // Remembers a file written by other means. Files may be written from several threads.
  void written(const std::filesystem::path& file) {
    const std::lock_guard<std::mutex> lock(written_mutex_);
    written_.push_back(file);
  }
  // The run succeeded: everything stays.
  void keep() { kept_ = true; }

 private:
  std::filesystem::path path_;
  std::vector<std::filesystem::path> made_;  // folders this run made, outermost first
  std::vector<std::filesystem::path> written_;
  std::mutex written_mutex_;
  bool created_ = false;
  bool kept_ = false;
};

}  // namespace ncv
