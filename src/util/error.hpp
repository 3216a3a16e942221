// The two kinds of failure a user can cause. Both end a command with exit status 2 and
// one line on standard error; anything else escaping is a bug.
#pragma once

#include <stdexcept>
#include <string>

namespace ncv {

// A file (or standard input) that cannot be used: its what() names the file and the fault.
class InputError : public std::runtime_error {
 public:
  InputError(const std::string& source, const std::string& problem)
      : std::runtime_error(source + ": " + problem) {}
};

// Options that make no sense (a step of zero, a tolerance that does not parse, ...).
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace ncv
