// Reading a whole input (a file, or standard input for "-") into memory.
#pragma once

#include <string>

#include "buffer.hpp"

namespace ncv {

// The display name of an input path: "standard input" for "-".
std::string input_name(const std::string& path);

// Reads everything; memory grows only with the bytes actually present, so no header
// count can make it allocate more. Throws InputError (missing file, directory, read error).
// The buffer is not zero-filled before read() fills it (a 62 MB STL: 15 ms instead of 50).
Buffer<char> read_input_bytes(const std::string& path);

}  // namespace ncv
