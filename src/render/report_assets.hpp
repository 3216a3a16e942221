// The HTML report's browser side, embedded at build time (CMakeLists.txt): the script
// (viewer/report_viewer.js bundled with three.js by esbuild) and the style sheet
// (viewer/report.css).
#pragma once

#include <string_view>

namespace ncv {

std::string_view report_viewer_script();
std::string_view report_style_sheet();

}  // namespace ncv
