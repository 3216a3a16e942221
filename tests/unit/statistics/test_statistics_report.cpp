// The stats report: JSON, CSV and text agree with the statistics and with each other.
#include <catch2/catch.hpp>

#include <sstream>

#include "statistics/statistics_report.hpp"

using namespace ncv;

namespace {

// A 10 × 10 square sampled finely, with d = x / 10 - 0.2: a linear field from -0.2 to 0.8.
DistanceSet linear_field_part() {
  Mesh square{{{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {10, 10, 0}}, {{0, 1, 2}, {3, 2, 1}}};
  DistanceSet set;
  set.samples = sample_mesh(std::move(square), 0.5, SamplingScheme::all);
  set.samples.source = "parts/plate.stl";
  set.samples.step_spec = "0.5";
  for (const Vec3& p : set.samples.positions) {
    set.field.distance.push_back(p[0] / 10 - 0.2);
    set.field.closest_face.push_back(0);
  }
  set.reference = {"plate_nominal.stl", 42, 2, {}};
  set.sign_method = "pseudonormal";
  set.search = "grid";
  return set;
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
  CHECK(verdict_status({make_part_report(part, Tolerance{-0.3, 0.9}, {}), {}}) == 0);
  const VerificationReport none{make_part_report(part, std::nullopt, {}), {}};
  CHECK(verdict_status(none) == 0);
  CHECK_FALSE(report_json(none).contains("tolerance"));
  CHECK_FALSE(report_json(none).contains("verdict"));
}

TEST_CASE("CSV rows have the header's columns, numbers round-trip", "[report]") {
  const DistanceSet part = linear_field_part();
  for (const std::optional<Tolerance> tolerance :
       {std::optional<Tolerance>{}, std::optional<Tolerance>{Tolerance{-1, 1}}}) {
    const VerificationReport report{make_part_report(part, tolerance, {}), {}};
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
  const std::string text = report_text(report);
  CHECK_THAT(text, Catch::Contains("reverse (nominal samples)"));
  CHECK_THAT(text, Catch::Contains("two-sided Hausdorff distance"));
  CHECK_THAT(text, Catch::EndsWith("verdict     FAIL\n"));
}
