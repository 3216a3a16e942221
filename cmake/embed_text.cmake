# Writes OUTPUT, a C++ source defining `std::string_view NAME()` that returns the text of
# INPUT, so that a file made at build time (the report's bundled script) becomes part of
# the binary. Usage: cmake -DINPUT=... -DOUTPUT=... -DNAME=... -P embed_text.cmake
file(READ "${INPUT}" text)
set(delimiter "ncv_embed")
string(FIND "${text}" ")${delimiter}\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "${INPUT} contains the raw-string delimiter )${delimiter}\"")
endif()
# Raw string literals of at most 16000 characters each: compilers cap one literal's length.
string(LENGTH "${text}" length)
set(pieces "")
set(offset 0)
while(offset LESS length)
  string(SUBSTRING "${text}" ${offset} 16000 piece)
  string(APPEND pieces "R\"${delimiter}(${piece})${delimiter}\"\n")
  math(EXPR offset "${offset} + 16000")
endwhile()
file(WRITE "${OUTPUT}.tmp" "// Generated from ${INPUT} by cmake/embed_text.cmake; do not edit.
#include <string_view>
namespace ncv {
std::string_view ${NAME}() {
  static constexpr char text[] =
${pieces};
  return {text, sizeof text - 1};
}
}  // namespace ncv
")
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
