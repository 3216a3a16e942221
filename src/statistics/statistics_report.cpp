#include "statistics/statistics_report.hpp"

#include <fmt/format.h>

#include <filesystem>

#include <tbb/parallel_invoke.h>

#include "geometry/point_json.hpp"
#include "util/error.hpp"

namespace ncv {
namespace {

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

bool forward(const PartReport& r) {
  return r.distances->direction == Direction::forward;
}

// The sampled surface: its counts and areas.
nlohmann::json sampled_json(const PartReport& r) {
  const DistanceSet& d = *r.distances;
  const ErrorStatistics& s = r.statistics;
  return {{"source", d.samples.source},
          {"hash", hash_hex(d.samples.mesh_hash)},
          {"triangles", s.triangles},
          {"area", s.workpiece_area},
          {"sampled_area", s.sampled_area},
          {"triangles_vertex_only", s.triangles_vertex_only},
          {"triangles_unsampled", s.triangles_unsampled}};
}

nlohmann::json reference_json(const PartReport& r) {
  const ReferenceInfo& reference = r.distances->reference;
  return {{"source", reference.source},
          {"hash", hash_hex(reference.hash)},
          {"triangles", reference.triangles}};
}

nlohmann::json tolerance_json(const PartReport& r) {
  const ToleranceAreas& t = *r.statistics.tolerance;
  const ErrorStatistics& s = r.statistics;
  return {
      {"lower", t.tolerance.lower},
      {"upper", t.tolerance.upper},
      {"area_within", t.within},
      {"area_excess", t.excess},
      {"area_gouge", t.gouge},
      {"share_within", s.share(t.within)},
      {"share_excess", s.share(t.excess)},
      {"share_gouge", s.share(t.gouge)},
      {"verdict", name_of(kVerdictNames, *r.verdict())},
      {"reason", verdict_reason(s, r.distances->certificate, t.tolerance, report_number_style(r))}};
}

nlohmann::json certificate_json(const Certificate& c) {
  return {{"width_asked", c.width_asked},
          {"max", certified_extreme_json(c.max)},
          {"min", certified_extreme_json(c.min)},
          {"max_width", c.max.width()},
          {"min_width", c.min.width()},
          {"sub_triangles", c.patches},
          {"sub_triangles_split", c.refined_patches},
          {"points_added", c.added_points},
          {"points_cap", c.points_cap},
          {"unresolved", c.unresolved},
          {"sign_proven", c.sign_proven}};
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

const char* verdict_word(Verdict verdict) {
  switch (verdict) {
    case Verdict::pass:
      return "PASS";
    case Verdict::fail:
      return "FAIL";
    case Verdict::inconclusive:
      break;
  }
  return "INCONCLUSIVE";
}

std::string direction_title(const PartReport& r) {
  return forward(r) ? "forward (workpiece samples)" : "reverse (nominal samples)";
}

void text_header(const std::vector<const PartReport*>& reports, const NumberStyle& n,
                 fmt::memory_buffer& out) {
  const PartReport& first = *reports.front();
  const auto sampled_line = [&](const PartReport& r) {
    return fmt::format("{}: {} triangles, area {}", r.distances->samples.source,
                       r.statistics.triangles, n.area_with_units(r.statistics.workpiece_area));
  };
  const auto reference_line = [](const PartReport& r) {
    return fmt::format("{}: {} triangles", r.distances->reference.source,
                       r.distances->reference.triangles);
  };
  const PartReport* forward_report = forward(first) ? &first : nullptr;
  const PartReport* reverse_report =
      reports.size() > 1 ? reports[1] : (forward(first) ? nullptr : &first);
  append(out, "part        {}\n", first.part);
  append(out, "workpiece   {}\n",
         forward_report ? sampled_line(*forward_report) : reference_line(*reverse_report));
  append(out, "nominal     {}\n",
         reverse_report ? sampled_line(*reverse_report) : reference_line(*forward_report));
  for (const PartReport* r : reports) {
    const DistanceSet& d = *r->distances;
    const ErrorStatistics& s = r->statistics;
    append(out,
           "{:<11} step {} ({}), scheme {}: {} samples of the {}; {} triangles sampled at their "
           "vertices only, {} not sampled; {} search, {:.2f} triangles tested per sample, sign "
           "by {}\n",
           name_of(kDirectionNames, d.direction), n.length_with_units(d.samples.step),
           d.samples.step_spec,
           d.samples.scheme == SamplingScheme::all ? "all (paper I)" : "paper-ii", s.samples,
           forward(*r) ? "workpiece" : "nominal", s.triangles_vertex_only, s.triangles_unsampled,
           d.search, d.triangles_tested_per_sample(), d.sign_method);
  }
  append(out, "\n");
}

// One row of the error table: a label and each direction's value.
template <class Value>
void text_row(fmt::memory_buffer& out, const std::string& label,
              const std::vector<const PartReport*>& reports, Value value) {
  append(out, "  {:<14}", label);
  for (const PartReport* r : reports) append(out, "{:<40}", value(*r));
  append(out, "\n");
}

void text_errors(const std::vector<const PartReport*>& reports, const NumberStyle& n,
                 fmt::memory_buffer& out) {
  append(out, "error in {} (signed: + material left, - gouge)\n", n.units);
  append(out, "  {:<14}", "");
  for (const PartReport* r : reports) append(out, "{:<40}", direction_title(*r));
  append(out, "\n");
  const auto number = [&](double value) { return n.length(value); };
  text_row(out, "max", reports,
           [&](const PartReport& r) { return number(r.statistics.max.value); });
  text_row(out, "min", reports,
           [&](const PartReport& r) { return number(r.statistics.min.value); });
  if (std::any_of(reports.begin(), reports.end(),
                  [](const PartReport* r) { return r->distances->certificate.has_value(); })) {
    // The certified interval of each extreme: its measured end and its proven bound.
    const auto interval = [&](const PartReport& r, bool upper) {
      const std::optional<Certificate>& c = r.distances->certificate;
      if (!c) return std::string("not certified");
      return upper
                 ? fmt::format("<= {} (measured {})", number(c->max.bound), number(c->max.measured))
                 : fmt::format(">= {} (measured {})", number(c->min.bound),
                               number(c->min.measured));
    };
    text_row(out, "max, proven", reports, [&](const PartReport& r) { return interval(r, true); });
    text_row(out, "min, proven", reports, [&](const PartReport& r) { return interval(r, false); });
  }
  text_row(out, "|d| max", reports,
           [&](const PartReport& r) { return number(r.statistics.max_abs.value); });
  text_row(out, "mean", reports, [&](const PartReport& r) { return number(r.statistics.mean); });
  text_row(out, "RMS", reports, [&](const PartReport& r) { return number(r.statistics.rms); });
  text_row(out, "std dev", reports,
           [&](const PartReport& r) { return number(r.statistics.std_dev); });
  const std::size_t percentiles = reports.front()->statistics.percentiles.size();
  for (std::size_t k = 0; k < percentiles; ++k) {
    text_row(out, fmt::format("{}%", reports.front()->statistics.percentiles[k].percent), reports,
             [&](const PartReport& r) { return number(r.statistics.percentiles[k].value); });
  }
  text_row(out, "sampled area", reports, [&](const PartReport& r) {
    return fmt::format("{} of {}", n.area(r.statistics.sampled_area),
                       n.area_with_units(r.statistics.workpiece_area));
  });
  for (const PartReport* r : reports) {
    append(out, "  {} max at {}, min at {}\n", name_of(kDirectionNames, r->distances->direction),
           n.point(r->statistics.max.position), n.point(r->statistics.min.position));
  }
}

void text_regions(const PartReport& r, const NumberStyle& n, fmt::memory_buffer& out) {
  if (r.regions.empty()) return;
  append(out, "\nout-of-tolerance regions, {}: {} excess, {} gouge (largest first)\n",
         name_of(kDirectionNames, r.distances->direction), count_regions(r, RegionKind::excess),
         count_regions(r, RegionKind::gouge));
  append(out, "  {:>3}  {:<6}  {:>14}  {:>12}  {}\n", "#", "kind", "area (" + n.units + "\u00b2)",
         "extreme (" + n.units + ")", "at");
  for (std::size_t k = 0; k < r.regions.size() && k < r.listed_regions; ++k) {
    const ErrorRegion& e = r.regions[k];
    append(out, "  {:>3}  {:<6}  {:>14}  {:>12}  {}\n", k + 1, kind_name(e.kind), n.area(e.area),
           n.length(e.extreme.value), n.point(e.extreme.position));
  }
  if (r.regions.size() > r.listed_regions) {
    append(out, "  ... {} more (all in the regions CSV)\n", r.regions.size() - r.listed_regions);
  }
}

void text_tolerance(const std::vector<const PartReport*>& reports, const NumberStyle& n,
                    fmt::memory_buffer& out) {
  const std::optional<ToleranceAreas>& zone = reports.front()->statistics.tolerance;
  if (!zone) return;
  append(out, "\ntolerance [{}, {}] {}\n", zone->tolerance.lower, zone->tolerance.upper, n.units);
  const auto share = [&](const PartReport& r, double ToleranceAreas::*area) {
    const ErrorStatistics& s = r.statistics;
    return fmt::format("{} ({:.2f} %)", n.area_with_units((*s.tolerance).*area),
                       100 * s.share((*s.tolerance).*area));
  };
  text_row(out, "within", reports,
           [&](const PartReport& r) { return share(r, &ToleranceAreas::within); });
  text_row(out, "excess", reports,
           [&](const PartReport& r) { return share(r, &ToleranceAreas::excess); });
  text_row(out, "gouge", reports,
           [&](const PartReport& r) { return share(r, &ToleranceAreas::gouge); });
  text_row(out, "verdict", reports,
           [&](const PartReport& r) { return std::string(verdict_word(*r.verdict())); });
  for (const PartReport* r : reports) {
    append(out, "  {}: {}\n", name_of(kDirectionNames, r->distances->direction),
           verdict_reason(r->statistics, r->distances->certificate, zone->tolerance, n));
  }
  for (const PartReport* r : reports) text_regions(*r, n, out);
}

std::vector<const PartReport*> directions(const VerificationReport& report) {
  std::vector<const PartReport*> reports = {&report.main};
  if (report.reverse) reports.push_back(&*report.reverse);
  return reports;
}

nlohmann::json direction_json(const PartReport& r) {
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
                      {"direction", name_of(kDirectionNames, d.direction)},
                      {"workpiece", forward(r) ? sampled_json(r) : reference_json(r)},
                      {"nominal", forward(r) ? reference_json(r) : sampled_json(r)},
                      {"sampling",
                       {{"step", d.samples.step},
                        {"step_spec", d.samples.step_spec},
                        {"scheme", name_of(kSamplingSchemeNames, d.samples.scheme)},
                        {"samples", s.samples}}},
                      {"distance",
                       {{"search", d.search},
                        {"sign_method", d.sign_method},
                        {"triangles_tested_per_sample", d.triangles_tested_per_sample()}}},
                      {"error",
                       {{"max", extreme_json(s.max)},
                        {"min", extreme_json(s.min)},
                        {"max_abs", extreme_json(s.max_abs)},
                        {"mean", s.mean},
                        {"rms", s.rms},
                        {"std_dev", s.std_dev},
                        {"percentiles", percentiles}}},
                      {"histogram", histogram}};
  if (d.certificate) {
    j["error"]["max"]["upper_bound"] = d.certificate->max.bound;
    j["error"]["min"]["lower_bound"] = d.certificate->min.bound;
    j["certificate"] = certificate_json(*d.certificate);
  }
  if (s.tolerance) {
    j["tolerance"] = tolerance_json(r);
    j["regions"] = regions_json(r);
    j["region_counts"] = {{"excess", count_regions(r, RegionKind::excess)},
                          {"gouge", count_regions(r, RegionKind::gouge)}};
  }
  return j;
}

nlohmann::json traceability_json(const VerificationReport& report) {
  const DistanceSet& d = *report.main.distances;
  const bool fwd = forward(report.main);
  const auto input = [](const char* role, const std::string& path, std::uint64_t hash,
                        std::uint64_t triangles) {
    return nlohmann::json{
        {"role", role}, {"path", path}, {"hash", hash_hex(hash)}, {"triangles", triangles}};
  };
  const nlohmann::json sampled = input(fwd ? "workpiece" : "nominal", d.samples.source,
                                       d.samples.mesh_hash, d.samples.mesh.triangle_count());
  const nlohmann::json reference = input(fwd ? "nominal" : "workpiece", d.reference.source,
                                         d.reference.hash, d.reference.triangles);
  return {
      {"version", report.trace.version},
      {"date", report.trace.date},
      {"command_line", report.trace.command_line},
      {"inputs", fwd ? nlohmann::json{sampled, reference} : nlohmann::json{reference, sampled}}};
}

std::string csv_quoted(const std::string& text) {
  std::string escaped;
  for (char c : text) escaped += c == '"' ? std::string("\"\"") : std::string(1, c);
  return "\"" + escaped + "\"";
}

}  // namespace

PartReport make_part_report(const DistanceSet& distances, const std::optional<Tolerance>& tolerance,
                            const HistogramOptions& histogram) {
  PartReport report;
  const std::string& workpiece = distances.direction == Direction::forward
                                     ? distances.samples.source
                                     : distances.reference.source;
  report.part = std::filesystem::path(workpiece).stem().string();
  report.distances = &distances;
  // Measured once: the numbers of every report, picture and page are rounded by it.
  report.surface_box = bounding_box(distances.samples.mesh);
  // The measures and the regions read the same distances and nothing of each other: they
  // run side by side, so that the regions' serial union-find overlaps the measures' passes.
  RegionMap regions;
  tbb::parallel_invoke(
      [&] {
        report.statistics = compute_error_statistics(distances.samples, distances.field.distance,
                                                     tolerance, histogram);
      },
      [&] {
        if (tolerance) {
          regions = map_error_regions(distances.samples, distances.field.distance, *tolerance);
        }
      });
  report.regions = std::move(regions.regions);
  report.sample_region = std::move(regions.sample_region);
  return report;
}

NumberStyle report_number_style(const PartReport& report) {
  return number_style(report.surface_box, report.units);
}

std::optional<Verdict> PartReport::verdict() const {
  if (!statistics.tolerance) return std::nullopt;
  return judge(statistics, distances->certificate, statistics.tolerance->tolerance);
}

namespace {

// One direction measured, passing, not asked for alone: the part is not proven by it.
bool awaits_other_direction(const VerificationReport& r) {
  return !r.reverse && !r.one_sided && r.main.verdict() == Verdict::pass;
}

}  // namespace

std::optional<Verdict> VerificationReport::verdict() const {
  if (awaits_other_direction(*this)) return Verdict::inconclusive;
  const std::optional<Verdict> first = main.verdict();
  if (!first || !reverse) return first;
  return worse(*first, *reverse->verdict());
}

std::string VerificationReport::missing_direction_reason() const {
  if (!awaits_other_direction(*this)) return {};
  if (forward(main)) {
    return "only the workpiece was measured against the nominal, and a nominal feature the "
           "workpiece lacks (a slot never cut) is not seen from that side: give the reverse "
           "distance file too (`distance --reverse`), or --one-sided to judge this direction "
           "alone";
  }
  return "only the nominal was measured against the workpiece, and material the workpiece has "
         "beyond the nominal's surface (a fin left standing) is not seen from that side: give "
         "the forward distance file too, or --one-sided to judge this direction alone";
}

std::optional<double> VerificationReport::hausdorff() const {
  if (!reverse) return std::nullopt;
  return std::max(main.statistics.max_abs.value, reverse->statistics.max_abs.value);
}

nlohmann::json report_json(const VerificationReport& report) {
  nlohmann::json j = direction_json(report.main);
  if (report.reverse) {
    j["reverse"] = direction_json(*report.reverse);
    j["hausdorff"] = *report.hausdorff();
  }
  if (const std::optional<Verdict> verdict = report.verdict()) {
    j["verdict"] = name_of(kVerdictNames, *verdict);
    if (const std::string why = report.missing_direction_reason(); !why.empty()) {
      j["reason"] = why;
    }
  }
  j["units"] = report.main.units;
  j["traceability"] = traceability_json(report);
  return j;
}

std::string report_text(const VerificationReport& report) {
  const std::vector<const PartReport*> reports = directions(report);
  const NumberStyle numbers = report_number_style(report.main);
  fmt::memory_buffer out;
  text_header(reports, numbers, out);
  text_errors(reports, numbers, out);
  if (const std::optional<double> h = report.hausdorff()) {
    append(out, "  two-sided Hausdorff distance {}\n", numbers.length_with_units(*h));
  }
  text_tolerance(reports, numbers, out);
  if (const std::optional<Verdict> verdict = report.verdict()) {
    append(out, "\nverdict     {}\n", verdict_word(*verdict));
    if (const std::string why = report.missing_direction_reason(); !why.empty()) {
      append(out, "            {}\n", why);
    }
  }
  return fmt::to_string(out);
}

std::string report_csv_header() {
  return "part,workpiece,nominal,triangles,samples,area,d_max,d_min,d_mean,rms,std_dev,max_abs,"
         "p1,p5,p50,p95,p99,tol_lower,tol_upper,area_within,area_excess,area_gouge,"
         "share_within,regions_excess,regions_gouge,reverse_d_max,reverse_d_min,hausdorff,"
         "max_upper_bound,min_lower_bound,reverse_max_upper_bound,reverse_min_lower_bound,"
         "verdict\n";
}

// The columns describe the forward direction (the only one measured, when a reverse file is
// reported alone); the reverse columns are empty without it.
std::string report_csv_row(const VerificationReport& report) {
  const PartReport& r = report.main;
  const ErrorStatistics& s = r.statistics;
  const DistanceSet& d = *r.distances;
  const bool fwd = forward(r);
  std::string row = fmt::format("{},{},{},{},{},{},{},{},{},{},{},{}", csv_quoted(r.part),
                                csv_quoted(fwd ? d.samples.source : d.reference.source),
                                csv_quoted(fwd ? d.reference.source : d.samples.source),
                                s.triangles, s.samples, s.workpiece_area, s.max.value, s.min.value,
                                s.mean, s.rms, s.std_dev, s.max_abs.value);
  for (const Percentile& p : s.percentiles) row += fmt::format(",{}", p.value);
  if (s.tolerance) {
    const ToleranceAreas& t = *s.tolerance;
    row += fmt::format(",{},{},{},{},{},{},{},{}", t.tolerance.lower, t.tolerance.upper, t.within,
                       t.excess, t.gouge, s.share(t.within), count_regions(r, RegionKind::excess),
                       count_regions(r, RegionKind::gouge));
  } else {
    row += ",,,,,,,,";
  }
  if (report.reverse) {
    row += fmt::format(",{},{},{}", report.reverse->statistics.max.value,
                       report.reverse->statistics.min.value, *report.hausdorff());
  } else {
    row += ",,,";
  }
  const auto bounds = [](const PartReport* p) {
    const std::optional<Certificate>* c = p ? &p->distances->certificate : nullptr;
    return c && *c ? fmt::format(",{},{}", (*c)->max.bound, (*c)->min.bound) : std::string(",,");
  };
  row += bounds(&r) + bounds(report.reverse ? &*report.reverse : nullptr);
  const std::optional<Verdict> verdict = report.verdict();
  row += verdict ? fmt::format(",{}", name_of(kVerdictNames, *verdict)) : ",";
  return row + "\n";
}

std::string regions_csv(const PartReport& r) {
  std::string csv =
      "region,kind,area,extreme,extreme_sample,extreme_x,extreme_y,extreme_z,samples,"
      "bbox_min_x,bbox_min_y,bbox_min_z,bbox_max_x,bbox_max_y,bbox_max_z\n";
  for (std::size_t k = 0; k < r.regions.size(); ++k) {
    const ErrorRegion& e = r.regions[k];
    const Vec3 p = e.extreme.position;
    csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", k + 1, kind_name(e.kind),
                       e.area, e.extreme.value, e.extreme.sample, p[0], p[1], p[2], e.samples,
                       e.box.min[0], e.box.min[1], e.box.min[2], e.box.max[0], e.box.max[1],
                       e.box.max[2]);
  }
  return csv;
}

std::string histogram_csv(const PartReport& r) {
  const Histogram& h = r.statistics.histogram;
  std::string csv = "bin,lo,hi,area,share\n";
  const auto share = [&](double area) { return h.total_area > 0 ? area / h.total_area : 0.0; };
  csv += fmt::format("below,,{},{},{}\n", h.range.lo, h.below_range, share(h.below_range));
  for (std::size_t k = 0; k < h.bin_count(); ++k) {
    csv +=
        fmt::format("{},{},{},{},{}\n", k, h.edge(k), h.edge(k + 1), h.area[k], share(h.area[k]));
  }
  csv += fmt::format("above,{},,{},{}\n", h.range.hi, h.above_range, share(h.above_range));
  return csv;
}

std::string format_report(const VerificationReport& report, ReportFormat format, bool csv_header) {
  switch (format) {
    case ReportFormat::json:
      return report_json(report).dump(2) + "\n";
    case ReportFormat::csv:
      return (csv_header ? report_csv_header() : "") + report_csv_row(report);
    case ReportFormat::text:
      break;
  }
  return report_text(report);
}

int verdict_status(const VerificationReport& report) {
  switch (report.verdict().value_or(Verdict::pass)) {
    case Verdict::pass:
      return 0;
    case Verdict::fail:
      return 1;
    case Verdict::inconclusive:
      break;
  }
  return 3;
}

}  // namespace ncv
