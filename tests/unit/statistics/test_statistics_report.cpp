// The stats report: JSON, CSV and text agree with the statistics and with each other.
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

#include "statistics/statistics_report.hpp"
#include "stats_fixtures.hpp"

using namespace ncv;

namespace {

// A certificate whose bounds are the given extremes, as certification proves them for a
// field that is linear over the surface.
Certificate certificate_of(double max, double min) {
  Certificate c;
  c.width_asked = 0.001;
  c.max = {max, {0, 0, 0}, max, {0, 0, 0}};
  c.min = {min, {0, 0, 0}, min, {0, 0, 0}};
  c.sign_proven = true;
  return c;
}

// A 10 × 10 square sampled finely, with d = x / 10 - 0.2: a linear field from -0.2 to 0.8,
// its extremes certified (a linear field is exactly its samples' interpolant).
DistanceSet linear_field_part() {
  Mesh square{{{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {10, 10, 0}}, {{0, 1, 2}, {3, 2, 1}}};
  DistanceSet set = test::linear_field_part(std::move(square), 0.5, "parts/plate.stl");
  set.samples.step_spec = "0.5";
  set.certificate = certificate_of(0.8, -0.2);
  return set;
}

// One direction judged on its own, as `stats --one-sided` and `run --one-sided` judge it.
VerificationReport one_sided(PartReport report) {
  return {std::move(report), std::nullopt, true};
}

std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (char c : line) {
    if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted)
      fields.emplace_back();
    else if (c != '\n')
      fields.back() += c;
  }
  return fields;
}

}  // namespace

TEST_CASE("the JSON report carries the statistics and the verdict", "[report]") {
  const DistanceSet part = linear_field_part();
  const VerificationReport report{make_part_report(part, Tolerance{-0.1, 0.5}, {}), {}};
  const nlohmann::json j = report_json(report);
  CHECK(j["part"] == "plate");
  CHECK(j["error"]["max"]["value"].get<double>() == Approx(0.8));
  CHECK(j["error"]["min"]["value"].get<double>() == Approx(-0.2));
  CHECK(j["error"]["mean"].get<double>() == Approx(0.3));  // linear field: mean of the ends
  CHECK(j["tolerance"]["verdict"] == "fail");
  // Excess where x/10 - 0.2 > 0.5: x > 7, 30 % of the plate; gouge where x < 1: 10 %.
  CHECK(j["tolerance"]["share_excess"].get<double>() == Approx(0.3));
  CHECK(j["tolerance"]["share_gouge"].get<double>() == Approx(0.1));
  CHECK(j["region_counts"]["excess"] == 1);
  CHECK(j["region_counts"]["gouge"] == 1);
  CHECK(j["regions"][0]["kind"] == "excess");  // the larger one first
  CHECK(verdict_status(report) == 1);
}

TEST_CASE("a passing part exits 0, and without a tolerance there is no verdict", "[report]") {
  const DistanceSet part = linear_field_part();
  CHECK(verdict_status(one_sided(make_part_report(part, Tolerance{-0.3, 0.9}, {}))) == 0);
  const VerificationReport none{make_part_report(part, std::nullopt, {}), {}};
  CHECK(verdict_status(none) == 0);
  CHECK_FALSE(report_json(none).contains("tolerance"));
  CHECK_FALSE(report_json(none).contains("verdict"));
}

TEST_CASE("pass needs certified bounds in the zone, samples alone are inconclusive",
          "[report][verdict]") {
  DistanceSet part = linear_field_part();
  const Tolerance zone{-0.3, 0.9};
  CHECK(verdict_status(one_sided(make_part_report(part, zone, {}))) == 0);
  // Between the samples the error may reach 0.95: not proven, exit status 3.
  part.certificate->max.bound = 0.95;
  const VerificationReport unproven = one_sided(make_part_report(part, zone, {}));
  CHECK(unproven.verdict() == Verdict::inconclusive);
  CHECK(verdict_status(unproven) == 3);
  CHECK(report_json(unproven)["verdict"] == "inconclusive");
  CHECK(report_json(unproven)["error"]["max"]["upper_bound"].get<double>() == 0.95);
  CHECK_THAT(report_json(unproven)["tolerance"]["reason"].get<std::string>(),
             Catch::Contains("may reach 0.95"));
  CHECK_THAT(report_text(unproven), Catch::EndsWith("verdict     INCONCLUSIVE\n"));
  // A point refinement measured beyond the zone fails, whatever the samples say.
  part.certificate->max.measured = 0.93;
  CHECK(verdict_status({make_part_report(part, zone, {}), {}}) == 1);
  // Without a certificate nothing bounds the error between samples.
  part.certificate.reset();
  const VerificationReport bare{make_part_report(part, zone, {}), {}};
  CHECK(bare.verdict() == Verdict::inconclusive);
  CHECK_FALSE(report_json(bare)["error"]["max"].contains("upper_bound"));
}

TEST_CASE("triangles left unsampled never pass", "[report][verdict]") {
  DistanceSet part = linear_field_part();
  PartReport report = make_part_report(part, Tolerance{-0.3, 0.9}, {});
  report.statistics.triangles_unsampled = 1;
  CHECK(report.verdict() == Verdict::inconclusive);
}

TEST_CASE("CSV rows have the header's columns, numbers round-trip", "[report]") {
  const DistanceSet part = linear_field_part();
  for (const std::optional<Tolerance> tolerance :
       {std::optional<Tolerance>{}, std::optional<Tolerance>{Tolerance{-1, 1}}}) {
    const VerificationReport report = one_sided(make_part_report(part, tolerance, {}));
    const auto header = csv_fields(report_csv_header());
    const auto row = csv_fields(report_csv_row(report));
    REQUIRE(header.size() == row.size());
    const auto column = [&](const std::string& name) {
      return row[std::find(header.begin(), header.end(), name) - header.begin()];
    };
    CHECK(std::stod(column("d_mean")) == report.main.statistics.mean);
    CHECK(std::stod(column("d_max")) == report.main.statistics.max.value);
    CHECK(column("reverse_d_max").empty());
    CHECK(column("part") == "plate");
    CHECK(column("verdict") == (tolerance ? "pass" : ""));
  }
}

TEST_CASE("the text report names the verdict and the regions", "[report]") {
  const DistanceSet part = linear_field_part();
  const std::string text = report_text({make_part_report(part, Tolerance{-0.1, 0.5}, {}), {}});
  CHECK_THAT(text, Catch::Contains("verdict     FAIL"));
  CHECK_THAT(text, Catch::Contains("1 excess, 1 gouge"));
  CHECK_THAT(text, Catch::Contains("plate_nominal.stl"));
}

// The plate measured in reverse: the same square as the nominal's samples, with the field
// d = -(x / 10 - 0.2) * 2, from 0.4 down to -1.6.
DistanceSet reverse_of(const DistanceSet& forward) {
  DistanceSet set;
  set.direction = Direction::reverse;
  set.samples = sample_mesh(forward.samples.mesh, 0.5, SamplingScheme::all);
  set.samples.source = "plate_nominal.stl";
  set.samples.step_spec = "0.5";
  for (const Vec3& p : set.samples.positions) {
    set.field.distance.push_back(-(p[0] / 10 - 0.2) * 2);
    set.field.closest_face.push_back(0);
  }
  set.reference = {"parts/plate.stl", 7, 2, {}};
  set.sign_method = "pseudonormal";
  set.search = "grid";
  set.certificate = certificate_of(0.4, -1.6);
  return set;
}

TEST_CASE("both directions: the reverse object, the Hausdorff distance, one verdict", "[report]") {
  const DistanceSet forward = linear_field_part();
  const DistanceSet reverse = reverse_of(forward);
  // Forward within [-0.3, 0.9]; reverse reaches -1.6, out of it.
  const VerificationReport report{make_part_report(forward, Tolerance{-0.3, 0.9}, {}),
                                  make_part_report(reverse, Tolerance{-0.3, 0.9}, {})};
  const nlohmann::json j = report_json(report);
  CHECK(j["tolerance"]["verdict"] == "pass");
  CHECK(j["reverse"]["tolerance"]["verdict"] == "fail");
  CHECK(j["verdict"] == "fail");
  CHECK(verdict_status(report) == 1);
  CHECK(j["direction"] == "forward");
  CHECK(j["reverse"]["direction"] == "reverse");
  CHECK(j["reverse"]["part"] == "plate");  // named after the workpiece in both directions
  CHECK(j["reverse"]["nominal"]["source"] == "plate_nominal.stl");  // the sampled surface
  CHECK(j["reverse"]["nominal"].contains("sampled_area"));
  CHECK(j["reverse"]["workpiece"]["source"] == "parts/plate.stl");
  CHECK_FALSE(j["reverse"]["workpiece"].contains("sampled_area"));
  CHECK(j["reverse"]["error"]["min"]["value"].get<double>() == Approx(-1.6));
  CHECK(j["hausdorff"].get<double>() == Approx(1.6));
  const auto header = csv_fields(report_csv_header());
  const auto row = csv_fields(report_csv_row(report));
  REQUIRE(header.size() == row.size());
  CHECK(header.back() == "verdict");
  CHECK(row.back() == "fail");
  const auto column = [&](const std::string& name) {
    return row[std::find(header.begin(), header.end(), name) - header.begin()];
  };
  CHECK(std::stod(column("reverse_d_min")) == report.reverse->statistics.min.value);
  CHECK(std::stod(column("reverse_d_max")) == report.reverse->statistics.max.value);
  CHECK(std::stod(column("hausdorff")) == *report.hausdorff());
  CHECK(std::stod(column("max_upper_bound")) == 0.8);
  CHECK(std::stod(column("reverse_min_lower_bound")) == -1.6);
  const std::string text = report_text(report);
  CHECK_THAT(text, Catch::Contains("reverse (nominal samples)"));
  CHECK_THAT(text, Catch::Contains("two-sided Hausdorff distance"));
  CHECK_THAT(text, Catch::EndsWith("verdict     FAIL\n"));
}

TEST_CASE("one direction passing alone is inconclusive unless judged one-sided",
          "[report][verdict]") {
  const DistanceSet forward = linear_field_part();
  const DistanceSet reverse = reverse_of(forward);
  const Tolerance zone{-0.3, 0.9};
  // The forward direction passes [-0.3, 0.9]; the reverse one, not given, would fail it.
  const VerificationReport alone{make_part_report(forward, zone, {}), std::nullopt};
  CHECK(alone.main.verdict() == Verdict::pass);
  CHECK(alone.verdict() == Verdict::inconclusive);
  CHECK(verdict_status(alone) == 3);
  const nlohmann::json j = report_json(alone);
  CHECK(j["tolerance"]["verdict"] == "pass");  // the direction's own verdict stands
  CHECK(j["verdict"] == "inconclusive");
  CHECK_THAT(j["reason"].get<std::string>(), Catch::Contains("--one-sided"));
  CHECK_THAT(j["reason"].get<std::string>(), Catch::Contains("distance --reverse"));
  CHECK_THAT(report_text(alone), Catch::Contains("verdict     INCONCLUSIVE\n            only the "
                                                 "workpiece was measured against the nominal"));
  CHECK(csv_fields(report_csv_row(alone)).back() == "inconclusive");
  // Judged on its own, it passes, with no reason added.
  const VerificationReport chosen = one_sided(make_part_report(forward, zone, {}));
  CHECK(chosen.verdict() == Verdict::pass);
  CHECK(chosen.missing_direction_reason().empty());
  CHECK_FALSE(report_json(chosen).contains("reason"));
  // The reverse file alone: the same, naming what the forward direction would see.
  const Tolerance wide{-2, 1};
  const VerificationReport reverse_alone{make_part_report(reverse, wide, {}), std::nullopt};
  CHECK(reverse_alone.verdict() == Verdict::inconclusive);
  CHECK_THAT(reverse_alone.missing_direction_reason(),
             Catch::Contains("only the nominal was measured against the workpiece"));
  // A failing direction fails the part whatever was measured the other way.
  const VerificationReport failing{make_part_report(forward, Tolerance{-0.1, 0.5}, {}),
                                   std::nullopt};
  CHECK(failing.verdict() == Verdict::fail);
  CHECK(failing.missing_direction_reason().empty());
  // An inconclusive direction stays inconclusive, for its own reason.
  DistanceSet unproven = forward;
  unproven.certificate->max.bound = 0.95;
  const VerificationReport doubt{make_part_report(unproven, zone, {}), std::nullopt};
  CHECK(doubt.verdict() == Verdict::inconclusive);
  CHECK(doubt.missing_direction_reason().empty());
  // Both directions given: no reason needed, whatever one_sided says.
  const VerificationReport both{make_part_report(forward, wide, {}),
                                make_part_report(reverse, wide, {})};
  CHECK(both.verdict() == Verdict::pass);
  CHECK(both.missing_direction_reason().empty());
}

TEST_CASE("the text report rounds to the part's resolution and names the units", "[report]") {
  DistanceSet part = linear_field_part();
  // Rounding noise where the field is 0, as exact arithmetic on float input leaves it.
  for (double& d : part.field.distance) {
    if (std::abs(d) < 1e-12) d = -1.5888e-14;
  }
  VerificationReport report{make_part_report(part, Tolerance{-0.1, 0.5}, {}), {}};
  report.main.units = "in";
  const std::string text = report_text(report);
  // The 10 x 10 plate: diagonal 14.1, resolution 1.4e-5, 5 decimals.
  CHECK_THAT(text, Catch::Contains("max           0.80000 "));
  CHECK_THAT(text, Catch::Contains("min           -0.20000 "));
  CHECK_THAT(text, Catch::Contains("error in in"));
  CHECK_THAT(text, Catch::Contains("tolerance [-0.1, 0.5] in"));
  CHECK_THAT(text, Catch::Contains("in\u00b2"));
  CHECK_THAT(text, Catch::Contains("sampled area  100.0000 of 100.0000 in\u00b2"));
  CHECK_THAT(text, !Catch::Contains("e-14"));
  CHECK_THAT(text, !Catch::Contains("00000000"));
  // JSON keeps every digit and says the units.
  const nlohmann::json j = report_json(report);
  CHECK(j["units"] == "in");
  CHECK(j["error"]["max"]["value"].get<double>() == report.main.statistics.max.value);
}

TEST_CASE("every region and every histogram bin as CSV, numbers round-trip", "[report]") {
  const DistanceSet part = linear_field_part();
  PartReport report = make_part_report(part, Tolerance{-0.1, 0.5}, {});
  report.listed_regions = 1;  // the CSV lists them all whatever the text shows
  std::istringstream regions(regions_csv(report));
  std::string line;
  std::getline(regions, line);
  const auto header = csv_fields(line);
  CHECK(header.front() == "region");
  std::size_t rows = 0;
  while (std::getline(regions, line)) {
    const auto row = csv_fields(line);
    REQUIRE(row.size() == header.size());
    const ErrorRegion& region = report.regions[rows];
    CHECK(std::stoul(row[0]) == rows + 1);
    CHECK(std::stod(row[2]) == region.area);
    CHECK(std::stod(row[3]) == region.extreme.value);
    ++rows;
  }
  CHECK(rows == report.regions.size());
  CHECK(rows == 2);

  std::istringstream histogram(histogram_csv(report));
  std::getline(histogram, line);
  CHECK(line == "bin,lo,hi,area,share");
  double total = 0;
  std::size_t bins = 0;
  while (std::getline(histogram, line)) {
    const auto row = csv_fields(line);
    REQUIRE(row.size() == 5);
    total += std::stod(row[3]);
    if (row[0] != "below" && row[0] != "above") {
      CHECK(std::stod(row[3]) == report.statistics.histogram.area[bins]);
      ++bins;
    }
  }
  CHECK(bins == report.statistics.histogram.bin_count());
  CHECK(total == Approx(report.statistics.histogram.total_area));
}

TEST_CASE("the JSON report traces the inputs and the command", "[report]") {
  const DistanceSet part = linear_field_part();
  VerificationReport report{make_part_report(part, std::nullopt, {}), {}};
  report.trace.date = "2026-01-02T03:04:05Z";
  report.trace.command_line = "ncverify stats plate.dist";
  const nlohmann::json t = report_json(report)["traceability"];
  CHECK(t["version"] == NCV_VERSION);
  CHECK(t["date"] == "2026-01-02T03:04:05Z");
  CHECK(t["command_line"] == "ncverify stats plate.dist");
  REQUIRE(t["inputs"].size() == 2);
  CHECK(t["inputs"][0]["role"] == "workpiece");
  CHECK(t["inputs"][0]["path"] == "parts/plate.stl");
  CHECK(t["inputs"][0]["triangles"] == 2);
  CHECK(t["inputs"][1]["role"] == "nominal");
  CHECK(t["inputs"][1]["path"] == "plate_nominal.stl");
  CHECK(t["inputs"][1]["hash"] == hash_hex(42));
}
