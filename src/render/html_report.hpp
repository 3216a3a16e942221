// The HTML report: one self-contained page a person can open offline in any current
// browser or e-mail to the shop floor. It holds the verdict, the inputs (names, triangle
// counts, content hashes), the parameters, the tool's version, the date and the command
// line, and for each direction of measurement its statistics, an interactive 3D view of
// the coloured surface (orbit, zoom, the error under the pointer, the worst points and
// every out-of-tolerance region marked, a region table whose rows bring the camera to the
// region), the colour legend and the area-weighted histogram.
//
// The page carries everything inline: the viewer script with three.js (report_assets.hpp),
// the style sheet, the display mesh (display_mesh.hpp) as base64, the pictures as SVG. Its
// Content-Security-Policy forbids every request, so opening it fetches nothing.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "render/color_map.hpp"
#include "render/display_mesh.hpp"
#include "statistics/statistics_report.hpp"

namespace ncv {

struct HtmlInput {
  std::string role;  // "workpiece", "nominal"
  std::string path;
  std::string hash;  // hex content hash
  std::uint64_t triangles = 0;
};

// One direction of measurement: its report, the colour map of its view and what the view
// draws.
struct HtmlDirection {
  std::string title;  // e.g. "Workpiece against the nominal"
  const PartReport* report = nullptr;
  ColorMap map;
  DisplayMesh display;
};

struct HtmlReport {
  std::string part;
  std::optional<Verdict> verdict;  // the part's, over every direction; none without a tolerance
  std::string missing_direction;   // why a direction's pass is not the part's (or empty)
  std::string units = "mm";
  Traceability trace;
  std::vector<HtmlInput> inputs;
  std::vector<std::pair<std::string, std::string>> parameters;  // name, value as shown
  std::vector<HtmlDirection> directions;
};

std::string html_report(const HtmlReport& report);

// The page of a part's verification: a section per direction measured (maps[0] colours the
// main one, maps[1] the reverse one when there is one), inputs and parameters from the
// distance files, the views' meshes within `budget` triangles together (an equal share
// each), so that the page stays about 10 MB.
HtmlReport verification_html_report(const VerificationReport& report,
                                    std::span<const ColorMap> maps,
                                    std::uint64_t budget = kDisplayTriangleBudget);

}  // namespace ncv
