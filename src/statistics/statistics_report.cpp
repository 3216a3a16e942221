#include "statistics/statistics_report.hpp"

#include <fmt/format.h>

#include <filesystem>

#include "util/error.hpp"

namespace ncv {
namespace {

nlohmann::json point_json(Vec3 p) {
  return {p[0], p[1], p[2]};
}

nlohmann::json extreme_json(const SampleExtreme& e) {
  return {{"value", e.value}, {"sample", e.sample}, {"position", point_json(e.position)}};
}

std::string kind_name(RegionKind kind) {
  return kind == RegionKind::excess ? "excess" : "gouge";
}

std::size_t count_regions(const PartReport& r, RegionKind kind) {
  return static_cast<std::size_t>(std::count_if(
      r.regions.begin(), r.regions.end(), [&](const ErrorRegion& e) { return e.kind == kind; }));
}

nlohmann::json tolerance_json(const PartReport& r) {
  const ToleranceAreas& t = *r.statistics.tolerance;
  const ErrorStatistics& s = r.statistics;
  return {{"lower", t.tolerance.lower},
          {"upper", t.tolerance.upper},
          {"area_within", t.within},
          {"area_excess", t.excess},
          {"area_gouge", t.gouge},
          {"share_within", s.share(t.within)},
          {"share_excess", s.share(t.excess)},
          {"share_gouge", s.share(t.gouge)},
          {"verdict", t.pass ? "pass" : "fail"}};
}

nlohmann::json regions_json(const PartReport& r) {
  nlohmann::json list = nlohmann::json::array();
  for (std::size_t k = 0; k < r.regions.size() && k < r.listed_regions; ++k) {
    const ErrorRegion& e = r.regions[k];
    list.push_back({{"kind", kind_name(e.kind)},
                    {"area", e.area},
                    {"extreme", extreme_json(e.extreme)},
                    {"samples", e.samples},
                    {"bbox_min", point_json(e.box.min)},
                    {"bbox_max", point_json(e.box.max)}});
  }
  return list;
}

template <class... Args>
void append(fmt::memory_buffer& out, fmt::format_string<Args...> format, Args&&... args) {
  fmt::format_to(std::back_inserter(out), format, std::forward<Args>(args)...);
}

std::string format_point(Vec3 p) {
  return fmt::format("({}, {}, {})", p[0], p[1], p[2]);
}

void text_header(const PartReport& r, fmt::memory_buffer& out) {
  const DistanceSet& d = *r.distances;
  const ErrorStatistics& s = r.statistics;
  append(out, "part        {}\n", r.part);
  append(out, "workpiece   {}: {} triangles, area {}\n", d.samples.source, s.triangles,
         s.workpiece_area);
  append(out, "nominal     {}: {} triangles\n", d.reference.source, d.reference.triangles);
  append(out,
         "sampling    step {} ({}), scheme {}: {} samples; {} triangles sampled at their vertices "
         "only, {} not sampled\n",
         d.samples.step, d.samples.step_spec,
         d.samples.scheme == SamplingScheme::all ? "all (paper I)" : "paper-ii", s.samples,
         s.triangles_vertex_only, s.triangles_unsampled);
  append(out, "distance    {} search, {} triangles tested per sample, sign by {}\n\n", d.search,
         d.triangles_tested_per_sample, d.sign_method);
}

void text_errors(const PartReport& r, fmt::memory_buffer& out) {
  const ErrorStatistics& s = r.statistics;
  append(out, "error (signed: + excess material, - gouge)\n");
  append(out, "  max         {:<24} at {}\n", s.max.value, format_point(s.max.position));
  append(out, "  min         {:<24} at {}\n", s.min.value, format_point(s.min.position));
  append(out, "  |d| max     {:<24} (one-sided Hausdorff)\n", s.max_abs.value);
  append(out, "  mean        {:<24} (area-weighted over the lattice)\n", s.mean);
  append(out, "  RMS         {}\n", s.rms);
  append(out, "  std dev     {}\n", s.std_dev);
  append(out, "  percentiles");
  for (const Percentile& p : s.percentiles) append(out, "  {}%: {}", p.percent, p.value);
  append(out, "\n  sampled area {} of {}\n", s.sampled_area, s.workpiece_area);
}

void text_tolerance(const PartReport& r, fmt::memory_buffer& out) {
  const ErrorStatistics& s = r.statistics;
  if (!s.tolerance) return;
  const ToleranceAreas& t = *s.tolerance;
  append(out, "\ntolerance [{}, {}]\n", t.tolerance.lower, t.tolerance.upper);
  append(out, "  within      area {:<22} {:6.2f} %\n", t.within, 100 * s.share(t.within));
  append(out, "  excess      area {:<22} {:6.2f} %\n", t.excess, 100 * s.share(t.excess));
  append(out, "  gouge       area {:<22} {:6.2f} %\n", t.gouge, 100 * s.share(t.gouge));
  append(out, "  verdict     {}\n", t.pass ? "PASS" : "FAIL");
  if (r.regions.empty()) return;
  append(out, "\nout-of-tolerance regions: {} excess, {} gouge (largest first)\n",
         count_regions(r, RegionKind::excess), count_regions(r, RegionKind::gouge));
  append(out, "  {:>3}  {:<6}  {:<22}  {:<22}  {}\n", "#", "kind", "area", "extreme", "at");
  for (std::size_t k = 0; k < r.regions.size() && k < r.listed_regions; ++k) {
    const ErrorRegion& e = r.regions[k];
    append(out, "  {:>3}  {:<6}  {:<22}  {:<22}  {}\n", k + 1, kind_name(e.kind), e.area,
           e.extreme.value, format_point(e.extreme.position));
  }
  if (r.regions.size() > r.listed_regions) {
    append(out, "  ... {} more\n", r.regions.size() - r.listed_regions);
  }
}

}  // namespace

PartReport make_part_report(const DistanceSet& distances, const std::optional<Tolerance>& tolerance,
                            const HistogramOptions& histogram) {
  PartReport report;
  report.part = std::filesystem::path(distances.samples.source).stem().string();
  report.distances = &distances;
  report.statistics =
      compute_error_statistics(distances.samples, distances.field.distance, tolerance, histogram);
  if (tolerance) {
    report.regions = find_error_regions(distances.samples, distances.field.distance, *tolerance);
  }
  return report;
}

nlohmann::json report_json(const PartReport& r) {
  const DistanceSet& d = *r.distances;
  const ErrorStatistics& s = r.statistics;
  nlohmann::json percentiles = nlohmann::json::object();
  for (const Percentile& p : s.percentiles) percentiles[fmt::format("p{}", p.percent)] = p.value;
  nlohmann::json histogram = {{"lo", s.histogram.range.lo},
                              {"hi", s.histogram.range.hi},
                              {"area", s.histogram.area},
                              {"below_range", s.histogram.below_range},
                              {"above_range", s.histogram.above_range}};
  nlohmann::json j = {{"part", r.part},
                      {"workpiece",
                       {{"source", d.samples.source},
                        {"hash", hash_hex(d.samples.mesh_hash)},
                        {"triangles", s.triangles},
                        {"area", s.workpiece_area},
                        {"sampled_area", s.sampled_area},
                        {"triangles_vertex_only", s.triangles_vertex_only},
                        {"triangles_unsampled", s.triangles_unsampled}}},
                      {"nominal",
                       {{"source", d.reference.source},
                        {"hash", hash_hex(d.reference.hash)},
                        {"triangles", d.reference.triangles}}},
                      {"sampling",
                       {{"step", d.samples.step},
                        {"step_spec", d.samples.step_spec},
                        {"scheme", name_of(kSamplingSchemeNames, d.samples.scheme)},
                        {"samples", s.samples}}},
                      {"distance",
                       {{"search", d.search},
                        {"sign_method", d.sign_method},
                        {"triangles_tested_per_sample", d.triangles_tested_per_sample}}},
                      {"error",
                       {{"max", extreme_json(s.max)},
                        {"min", extreme_json(s.min)},
                        {"max_abs", extreme_json(s.max_abs)},
                        {"mean", s.mean},
                        {"rms", s.rms},
                        {"std_dev", s.std_dev},
                        {"percentiles", percentiles}}},
                      {"histogram", histogram}};
  if (s.tolerance) {
    j["tolerance"] = tolerance_json(r);
    j["regions"] = regions_json(r);
    j["region_counts"] = {{"excess", count_regions(r, RegionKind::excess)},
                          {"gouge", count_regions(r, RegionKind::gouge)}};
  }
  return j;
}

std::string report_text(const PartReport& r) {
  fmt::memory_buffer out;
  text_header(r, out);
  text_errors(r, out);
  text_tolerance(r, out);
  return fmt::to_string(out);
}

std::string report_csv_header() {
  return "part,workpiece,nominal,triangles,samples,area,d_max,d_min,d_mean,rms,std_dev,max_abs,"
         "p1,p5,p50,p95,p99,tol_lower,tol_upper,area_within,area_excess,area_gouge,"
         "share_within,regions_excess,regions_gouge,verdict\n";
}

std::string report_csv_row(const PartReport& r) {
  const ErrorStatistics& s = r.statistics;
  auto quoted = [](const std::string& text) {
    std::string escaped;
    for (char c : text) escaped += c == '"' ? std::string("\"\"") : std::string(1, c);
    return "\"" + escaped + "\"";
  };
  std::string row = fmt::format(
      "{},{},{},{},{},{},{},{},{},{},{},{}", quoted(r.part), quoted(r.distances->samples.source),
      quoted(r.distances->reference.source), s.triangles, s.samples, s.workpiece_area, s.max.value,
      s.min.value, s.mean, s.rms, s.std_dev, s.max_abs.value);
  for (const Percentile& p : s.percentiles) row += fmt::format(",{}", p.value);
  if (s.tolerance) {
    const ToleranceAreas& t = *s.tolerance;
    row +=
        fmt::format(",{},{},{},{},{},{},{},{},{}", t.tolerance.lower, t.tolerance.upper, t.within,
                    t.excess, t.gouge, s.share(t.within), count_regions(r, RegionKind::excess),
                    count_regions(r, RegionKind::gouge), t.pass ? "pass" : "fail");
  } else {
    row += ",,,,,,,,,";
  }
  return row + "\n";
}

std::string format_report(const PartReport& r, ReportFormat format, bool csv_header) {
  switch (format) {
    case ReportFormat::json:
      return report_json(r).dump(2) + "\n";
    case ReportFormat::csv:
      return (csv_header ? report_csv_header() : "") + report_csv_row(r);
    case ReportFormat::text:
      break;
  }
  return report_text(r);
}

int verdict_status(const PartReport& r) {
  return r.statistics.tolerance && !r.statistics.tolerance->pass ? 1 : 0;
}

}  // namespace ncv
