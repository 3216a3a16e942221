// STL parsing (binary and ASCII) straight into a welded Mesh.
#pragma once

#include <span>
#include <string>

#include "mesh/mesh.hpp"

namespace ncv {

// True when the size matches 84 + 50 × the header's triangle count.
bool looks_like_binary_stl(std::span<const char> bytes);
bool looks_like_ascii_stl(std::span<const char> bytes);

// Both throw InputError(source, ...) on malformed input.
Mesh parse_binary_stl(std::span<const char> bytes, const std::string& source);
Mesh parse_ascii_stl(std::span<const char> bytes, const std::string& source);

}  // namespace ncv
