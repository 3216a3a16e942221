// The HTML report: one page that carries everything it shows and asks the network for
// nothing; its data agree with the report. (The page itself is tried in a real browser by
// tests/e2e/test_html_report.sh.)
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "render/html_report.hpp"
#include "render/report_assets.hpp"
#include "stats_fixtures.hpp"

using namespace ncv;

namespace {

// A 10 x 10 plate with d = x / 10 - 0.2, as the stats report tests use.
DistanceSet plate() {
  DistanceSet set = test::linear_field_part(test::flat_grid(4, 10.0), 0.25, "parts/plate<1>.stl");
  set.samples.step_spec = "0.25";
  set.samples.mesh_hash = 0x1234;
  return set;
}

// The plate with d from -0.2 to 0.8 measured, the min proven there and the max bounded by
// max_bound near `at`.
DistanceSet certified_plate(double max_bound, Vec3 at) {
  DistanceSet part = plate();
  Certificate c;
  c.width_asked = 0.001;
  c.max = {0.8, Vec3(10, 0, 0), max_bound, at};
  c.min = {-0.2, Vec3(0, 0, 0), -0.2, Vec3(0, 0, 0)};
  c.sign_proven = true;
  part.certificate = c;
  return part;
}

std::string element_text(const std::string& html, const std::string& opening) {
  const std::size_t at = html.find(opening);
  REQUIRE(at != std::string::npos);
  const std::size_t begin = at + opening.size();
  return html.substr(begin, html.find("</script>", begin) - begin);
}

std::size_t count_of(const std::string& text, const std::string& part) {
  std::size_t count = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) {
    ++count;
  }
  return count;
}

std::size_t base64_bytes(const std::string& text) {
  const std::size_t padding = text.empty() ? 0 : count_of(text.substr(text.size() - 2), "=");
  return text.size() / 4 * 3 - padding;
}

}  // namespace

TEST_CASE("the HTML report is one page that needs nothing from outside", "[html]") {
  const DistanceSet part = plate();
  VerificationReport verification{make_part_report(part, Tolerance{-0.1, 0.5}, {}), {}};
  verification.trace.date = "2026-01-02T03:04:05Z";
  verification.trace.command_line = "ncverify report plate.dist --tol -0.1:0.5";
  const PartReport& report = verification.main;
  const ColorMap maps[] = {
      make_color_map(ColorMapKind::tolerance, {-0.2, 0.8}, Tolerance{-0.1, 0.5})};
  const std::string html = html_report(verification_html_report(verification, maps));

  CHECK(html.rfind("<!DOCTYPE html>", 0) == 0);
  CHECK_THAT(html, Catch::Contains("Content-Security-Policy"));
  CHECK_THAT(html, Catch::Contains("default-src 'none'"));
  // Nothing refers to another file: no element loads a source or a style sheet.
  for (const char* reference : {"<link", " src=", "href=\"http", "@import", "<iframe", "<img"}) {
    INFO(reference);
    CHECK(html.find(reference) == std::string::npos);
  }
  CHECK(html.find(report_viewer_script()) != std::string::npos);
  CHECK(html.find(report_style_sheet()) != std::string::npos);

  // Verdict, inputs (escaped), parameters, traceability.
  CHECK_THAT(html, Catch::Contains("FAIL \u2014 out of tolerance"));
  CHECK_THAT(html, Catch::Contains("parts/plate&lt;1&gt;.stl"));
  CHECK_THAT(html, Catch::Contains(hash_hex(0x1234)));
  CHECK_THAT(html, Catch::Contains("[-0.1, 0.5] mm"));
  CHECK_THAT(html, Catch::Contains("2026-01-02T03:04:05Z"));
  CHECK_THAT(html, Catch::Contains("ncverify report plate.dist --tol -0.1:0.5"));

  // One table row per region, each naming its number for the viewer.
  REQUIRE(report.regions.size() == 2);
  CHECK(count_of(html, "<tr data-region=") == 2);
  CHECK_THAT(html, Catch::Contains("<tr data-region=\"2\""));

  // The view's data: the display mesh, whole, in the layout the viewer reads.
  const nlohmann::json view = nlohmann::json::parse(
      element_text(html, "<script type=\"application/json\" id=\"ncv-view-0\">"));
  const std::uint64_t vertices = view["vertexCount"], triangles = view["triangleCount"];
  CHECK(vertices == part.samples.sample_count());  // small enough to show every sample
  CHECK(view["regions"].size() == 2);
  CHECK(view["worst"][0]["value"].get<double>() == report.statistics.max.value);
  CHECK(view["units"] == "mm");
  const std::string mesh =
      element_text(html, "<script type=\"application/octet-stream\" id=\"ncv-mesh-0\">");
  CHECK(base64_bytes(mesh) == vertices * (12 + 4 + 4 + 3) + triangles * 12);
  CHECK(
      mesh.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/=") ==
      std::string::npos);
  // Legend and histogram inline, with the part's name.
  CHECK(count_of(html, "<svg") == 2);
  CHECK_THAT(html, Catch::Contains("id=\"ncv-bar-0\""));
  CHECK_THAT(html, Catch::Contains("url(#ncv-bar-0)"));
}

TEST_CASE("without a tolerance the page says there is no verdict", "[html]") {
  const DistanceSet part = plate();
  const VerificationReport report{make_part_report(part, std::nullopt, {}), {}};
  const ColorMap maps[] = {make_color_map(ColorMapKind::diverging, {-0.8, 0.8}, std::nullopt)};
  const std::string html = html_report(verification_html_report(report, maps));
  CHECK_THAT(html, Catch::Contains("No verdict"));
  CHECK_THAT(html, !Catch::Contains("data-region="));
}

TEST_CASE("text that would end a script element is escaped in the page's data", "[html]") {
  DistanceSet part = plate();
  part.samples.source = "x</script><script>alert(1)</script>.stl";
  const VerificationReport report{make_part_report(part, Tolerance{-1, 1}, {}), {}};
  const ColorMap maps[] = {make_color_map(ColorMapKind::tolerance, {-1, 1}, Tolerance{-1, 1})};
  const std::string html = html_report(verification_html_report(report, maps));
  CHECK_THAT(html, !Catch::Contains("<script>alert"));
}

TEST_CASE("a part not proven within tolerance gets the inconclusive banner and its bounds",
          "[html]") {
  // Measured within [-0.3, 0.9] (d runs from -0.2 to 0.8), but between the samples the error
  // may reach 0.95.
  const DistanceSet part = certified_plate(0.95, Vec3(9.5, 1, 0));
  const VerificationReport report{make_part_report(part, Tolerance{-0.3, 0.9}, {}), {}};
  const ColorMap maps[] = {make_color_map(ColorMapKind::diverging, {-0.8, 0.8}, std::nullopt)};
  const std::string html = html_report(verification_html_report(report, maps));
  CHECK_THAT(html, Catch::Contains("ncv-verdict ncv-inconclusive"));
  CHECK_THAT(html, Catch::Contains("INCONCLUSIVE \u2014 not proven within tolerance"));
  CHECK_THAT(html, Catch::Contains("may reach 0.95"));
  CHECK_THAT(html, Catch::Contains("max, proven"));
  CHECK_THAT(html, Catch::Contains("\u2264 0.95"));
}

TEST_CASE("one direction that passes, not asked for alone, gets the inconclusive banner",
          "[html][verdict]") {
  const DistanceSet part = certified_plate(0.8, Vec3(10, 0, 0));
  const ColorMap maps[] = {make_color_map(ColorMapKind::diverging, {-0.8, 0.8}, std::nullopt)};
  VerificationReport report{make_part_report(part, Tolerance{-0.3, 0.9}, {}), std::nullopt};
  const std::string alone = html_report(verification_html_report(report, maps));
  CHECK_THAT(alone, Catch::Contains("ncv-verdict ncv-inconclusive"));
  CHECK_THAT(alone, Catch::Contains("Not proven: only the workpiece was measured"));
  report.one_sided = true;
  const std::string chosen = html_report(verification_html_report(report, maps));
  CHECK_THAT(chosen, Catch::Contains("ncv-verdict ncv-pass"));
  CHECK_THAT(chosen, !Catch::Contains("Not proven"));
}
