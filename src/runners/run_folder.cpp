#include "runners/run_folder.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "util/error.hpp"

namespace ncv {

namespace fs = std::filesystem;

namespace {

// The nearest folder at or above `path` that exists ("." for a relative path with none).
fs::path existing_ancestor(const fs::path& path) {
  fs::path at = path;
  std::error_code error;
  while (!at.empty() && !fs::exists(at, error)) at = at.parent_path();
  return at.empty() ? fs::path(".") : at;
}

void check_writable_folder(const fs::path& folder, const std::string& shown) {
  std::error_code error;
  if (!fs::is_directory(folder, error)) {
    throw InputError(shown, "cannot write: " + folder.string() + " is not a folder");
  }
  if (::access(folder.c_str(), W_OK | X_OK) != 0) {
    throw InputError(shown, std::string("cannot write: ") + std::strerror(errno));
  }
}

}  // namespace

void check_writable(const std::string& path) {
  if (path.empty() || path == "-") return;
  const fs::path parent = fs::path(path).parent_path();
  const fs::path folder = parent.empty() ? fs::path(".") : parent;
  std::error_code error;
  if (!fs::exists(folder, error)) {
    throw InputError(path, "cannot write: " + folder.string() + " does not exist");
  }
  check_writable_folder(folder, path);
  if (fs::is_directory(path, error)) throw InputError(path, "cannot write: it is a folder");
}

RunFolder::RunFolder(fs::path path) : path_(std::move(path)) {
  std::error_code error;
  if (fs::exists(path_, error)) {
    check_writable_folder(path_, path_.string());
  } else {
    check_writable_folder(existing_ancestor(path_), path_.string());
  }
}

RunFolder::~RunFolder() {
  if (kept_) return;
  std::error_code ignored;
  for (const fs::path& file : written_) fs::remove(file, ignored);
  // Innermost first; a folder something else wrote into stays.
  for (auto folder = made_.rbegin(); folder != made_.rend(); ++folder) fs::remove(*folder, ignored);
}

void RunFolder::create() {
  if (created_) return;
  for (fs::path at = path_; !at.empty(); at = at.parent_path()) {
    std::error_code error;
    if (fs::exists(at, error)) break;
    made_.insert(made_.begin(), at);
  }
  std::error_code error;
  fs::create_directories(path_, error);
  if (error) {
    throw InputError(path_.string(), "cannot create the output folder: " + error.message());
  }
  created_ = true;
}

}  // namespace ncv
