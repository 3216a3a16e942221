#include "render/html_report.hpp"

#include <bit>
#include <sstream>

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <nlohmann/json.hpp>

#include "geometry/point_json.hpp"
#include "render/report_assets.hpp"
#include "render/svg_histogram.hpp"
#include "render/svg_legend.hpp"
#include "render/svg_text.hpp"
#include "statistics/readable_numbers.hpp"

namespace ncv {

namespace {

// Forbids every request: the page is complete as it is, and must stay so when opened.
constexpr const char* kContentSecurityPolicy =
    "default-src 'none'; script-src 'unsafe-inline'; style-src 'unsafe-inline'; "
    "img-src data: blob:";

// Region rows beyond this are counted, not listed (all are in the regions CSV and marked
// in the view).
constexpr std::size_t kMostRegionRows = 5000;

// The banner's four states: the three verdicts, and none without a tolerance.
enum class Banner { pass, fail, inconclusive, none };

Banner banner_of(const HtmlReport& report) {
  if (!report.verdict) return Banner::none;
  switch (*report.verdict) {
    case Verdict::pass:
      return Banner::pass;
    case Verdict::fail:
      return Banner::fail;
    case Verdict::inconclusive:
      break;
  }
  return Banner::inconclusive;
}

std::string esc(std::string_view text) {
  return xml_escaped(text);
}

template <class... Args>
void append(std::string& out, fmt::format_string<Args...> format, Args&&... args) {
  fmt::format_to(std::back_inserter(out), format, std::forward<Args>(args)...);
}

// Whole groups of three bytes become four digits each, in parallel blocks written at their
// places (appending a character at a time took most of the page's 30 ms of text).
std::string base64(const std::string& bytes) {
  static constexpr char kDigits[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const std::size_t groups = bytes.size() / 3;
  std::string out((bytes.size() + 2) / 3 * 4, '=');
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, groups, 1 << 15), [&](const auto& range) {
    for (std::size_t g = range.begin(); g != range.end(); ++g) {
      const std::size_t k = 3 * g;
      const std::uint32_t v = static_cast<std::uint8_t>(bytes[k]) << 16 |
                              static_cast<std::uint8_t>(bytes[k + 1]) << 8 |
                              static_cast<std::uint8_t>(bytes[k + 2]);
      char* at = out.data() + 4 * g;
      for (int shift = 18; shift >= 0; shift -= 6) *at++ = kDigits[v >> shift & 63];
    }
  });
  const std::size_t k = 3 * groups, rest = bytes.size() - k;
  if (rest > 0) {
    std::uint32_t v = static_cast<std::uint8_t>(bytes[k]) << 16;
    if (rest == 2) v |= static_cast<std::uint8_t>(bytes[k + 1]) << 8;
    char* at = out.data() + 4 * groups;
    at[0] = kDigits[v >> 18 & 63];
    at[1] = kDigits[v >> 12 & 63];
    if (rest == 2) at[2] = kDigits[v >> 6 & 63];
  }
  return out;
}

char* put_u32(char* at, std::uint32_t value) {
  for (int shift = 0; shift < 32; shift += 8) *at++ = static_cast<char>(value >> shift & 0xff);
  return at;
}

char* put_f32(char* at, double value) {
  return put_u32(at, std::bit_cast<std::uint32_t>(static_cast<float>(value)));
}

// The layout viewer/report_viewer.js reads: positions relative to `center` (float32 x 3),
// values (float32), regions (uint32), triangle corners (uint32 x 3), colours (uint8 x 3).
// Fixed-size records, each section filled in parallel at its place.
std::string mesh_bytes(const ErrorMesh& m, const ColorMap& map, Vec3 center) {
  const std::size_t vertices = m.mesh.vertex_count(), triangles = m.mesh.triangle_count();
  std::string out(vertices * 23 + triangles * 12, '\0');
  char* const points = out.data();
  char* const values = points + vertices * 12;
  char* const regions = values + vertices * 4;
  char* const corners = regions + vertices * 4;
  char* const colours = corners + triangles * 12;
  const auto each = [](std::size_t count, auto&& fill) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 1 << 14), [&](const auto& r) {
      for (std::size_t i = r.begin(); i != r.end(); ++i) fill(i);
    });
  };
  each(vertices, [&](std::size_t v) {
    char* at = points + 12 * v;
    for (int k = 0; k < 3; ++k) at = put_f32(at, m.mesh.vertices[v][k] - center[k]);
    put_f32(values + 4 * v, m.values[v]);
    put_u32(regions + 4 * v, m.regions[v]);
    const Rgb rgb = map.rgb(m.values[v]);
    for (int k = 0; k < 3; ++k) colours[3 * v + k] = static_cast<char>(rgb[k]);
  });
  each(triangles, [&](std::size_t t) {
    char* at = corners + 12 * t;
    for (const std::uint32_t v : m.mesh.triangles[t]) at = put_u32(at, v);
  });
  return out;
}

std::string kind_name(RegionKind kind) {
  return kind == RegionKind::excess ? "excess" : "gouge";
}

// JSON inside a <script> element: "</" would end the element early.
std::string script_json(const nlohmann::json& json) {
  std::string text = json.dump();
  std::string out;
  out.reserve(text.size());
  for (std::size_t k = 0; k < text.size(); ++k) {
    out += text[k];
    if (text[k] == '<' && k + 1 < text.size() && text[k + 1] == '/') out += '\\';
  }
  return out;
}

nlohmann::json view_json(const HtmlDirection& d, std::size_t index, Vec3 center,
                         const NumberStyle& numbers) {
  const ErrorStatistics& s = d.report->statistics;
  nlohmann::json regions = nlohmann::json::array();
  for (const ErrorRegion& r : d.report->regions) {
    regions.push_back({{"kind", kind_name(r.kind)},
                       {"area", r.area},
                       {"extreme", r.extreme.value},
                       {"at", point_json(r.extreme.position)},
                       {"boxMin", point_json(r.box.min)},
                       {"boxMax", point_json(r.box.max)}});
  }
  return {{"title", d.title},
          {"meshId", fmt::format("ncv-mesh-{}", index)},
          {"vertexCount", d.display.mesh.mesh.vertex_count()},
          {"triangleCount", d.display.mesh.mesh.triangle_count()},
          {"center", point_json(center)},
          {"units", numbers.units},
          {"decimals", numbers.length_decimals},
          {"worst",
           {{{"label", "max"}, {"value", s.max.value}, {"at", point_json(s.max.position)}},
            {{"label", "min"}, {"value", s.min.value}, {"at", point_json(s.min.position)}}}},
          {"regions", regions}};
}

std::string inline_svg(std::string svg, std::size_t index) {
  const std::size_t start = svg.find("<svg");
  svg = svg.substr(start == std::string::npos ? 0 : start);
  // Element ids must be unique in the page: one legend per direction.
  const std::string id = fmt::format("ncv-bar-{}", index);
  for (std::size_t at = svg.find("ncv-bar\""); at != std::string::npos;
       at = svg.find("ncv-bar\"", at + 1)) {
    svg.replace(at, 7, id);
  }
  for (std::size_t at = svg.find("#ncv-bar)"); at != std::string::npos;
       at = svg.find("#ncv-bar)", at + 1)) {
    svg.replace(at + 1, 7, id);
  }
  return svg;
}

std::string short_title(const PartReport& r) {
  return r.distances->direction == Direction::forward ? "Workpiece against nominal"
                                                      : "Nominal against workpiece";
}

std::string banner_reason(const HtmlReport& report, const NumberStyle& n) {
  std::string reason;
  if (!report.missing_direction.empty())
    append(reason, "Not proven: {}. ", report.missing_direction);
  for (const HtmlDirection& d : report.directions) {
    const ErrorStatistics& s = d.report->statistics;
    const std::string title = short_title(*d.report);
    if (!s.tolerance) {
      append(reason, "{}: no tolerance given; max {}, min {}. ", title,
             n.length_with_units(s.max.value), n.length_with_units(s.min.value));
      continue;
    }
    append(reason, "{}: {}", title,
           verdict_reason(s, d.report->distances->certificate, s.tolerance->tolerance, n));
    if (!d.report->regions.empty()) {
      append(reason, "; {} regions out of tolerance, {:.2f} % of the area",
             d.report->regions.size(), 100 * (1 - s.share(s.tolerance->within)));
    }
    reason += ". ";
  }
  return reason;
}

void write_head(std::string& out, const HtmlReport& report, Banner verdict) {
  static constexpr const char* kVerdictWord[] = {"PASS", "FAIL", "INCONCLUSIVE", "no tolerance"};
  append(out,
         "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta http-equiv=\"Content-Security-Policy\" content=\"{}\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         "<meta name=\"generator\" content=\"ncverify {}\">\n"
         "<title>{}: {} \u2014 ncverify report</title>\n<style>\n{}</style>\n</head>\n<body>\n",
         kContentSecurityPolicy, esc(report.trace.version), esc(report.part),
         kVerdictWord[static_cast<int>(verdict)], report_style_sheet());
}

void write_banner(std::string& out, const HtmlReport& report, Banner verdict,
                  const NumberStyle& n) {
  static constexpr const char* kClass[] = {"ncv-pass", "ncv-fail", "ncv-inconclusive", "ncv-none"};
  static constexpr const char* kHeadline[] = {
      "PASS \u2014 proven within tolerance", "FAIL \u2014 out of tolerance",
      "INCONCLUSIVE \u2014 not proven within tolerance", "No verdict \u2014 no tolerance given"};
  append(out, "<div class=\"ncv-verdict {}\" id=\"ncv-verdict\">{}: {}<small>{}</small></div>\n",
         kClass[static_cast<int>(verdict)], esc(report.part), kHeadline[static_cast<int>(verdict)],
         esc(banner_reason(report, n)));
}

void write_facts(std::string& out, const HtmlReport& report) {
  out +=
      "<div class=\"ncv-columns\">\n<div>\n<h2>Inputs</h2>\n<table class=\"ncv-facts\">\n"
      "<tr><th>role</th><th>file</th><th class=\"num\">triangles</th>"
      "<th>content hash (XXH3-64)</th></tr>\n";
  for (const HtmlInput& input : report.inputs) {
    append(out,
           "<tr><td>{}</td><td><code>{}</code></td><td class=\"num\">{}</td>"
           "<td><code>{}</code></td></tr>\n",
           esc(input.role), esc(input.path), input.triangles, esc(input.hash));
  }
  out += "</table>\n</div>\n<div>\n<h2>Parameters</h2>\n<table class=\"ncv-facts\">\n";
  for (const auto& [name, value] : report.parameters) {
    append(out, "<tr><th>{}</th><td>{}</td></tr>\n", esc(name), esc(value));
  }
  append(out,
         "</table>\n</div>\n</div>\n<p class=\"ncv-note\">Made by ncverify {} on {} with "
         "<code>{}</code></p>\n",
         esc(report.trace.version), esc(report.trace.date), esc(report.trace.command_line));
}

void stat_row(std::string& out, std::string_view name, const std::string& value,
              std::string_view note = {}) {
  append(out, "<tr><th>{}</th><td class=\"num\">{}</td><td>{}</td></tr>\n", esc(name), esc(value),
         esc(note));
}

void write_statistics(std::string& out, const PartReport& r, const NumberStyle& n) {
  const ErrorStatistics& s = r.statistics;
  out += "<table class=\"ncv-facts ncv-statistics\">\n";
  append(out, "<tr><th>signed error ({})</th><th class=\"num\">value</th><th></th></tr>\n",
         esc(n.units));
  stat_row(out, "max", n.length(s.max.value), "at " + n.point(s.max.position));
  stat_row(out, "min", n.length(s.min.value), "at " + n.point(s.min.position));
  if (const std::optional<Certificate>& c = r.distances->certificate) {
    // The certified bounds: no point of the surface, between the samples too, goes beyond.
    stat_row(out, "max, proven", "\u2264 " + n.length(c->max.bound),
             fmt::format("measured {} between samples; the bound near {}",
                         n.length(c->max.measured), n.point(c->max.bound_at)));
    stat_row(out, "min, proven", "\u2265 " + n.length(c->min.bound),
             fmt::format("measured {} between samples; the bound near {}",
                         n.length(c->min.measured), n.point(c->min.bound_at)));
  }
  stat_row(out, "|d| max", n.length(s.max_abs.value), "one-sided Hausdorff distance");
  stat_row(out, "mean", n.length(s.mean), "area-weighted over the lattice");
  stat_row(out, "RMS", n.length(s.rms));
  stat_row(out, "std dev", n.length(s.std_dev));
  for (const Percentile& p : s.percentiles) {
    stat_row(out, fmt::format("{} % percentile", p.percent), n.length(p.value), "of the area");
  }
  stat_row(out, "samples", fmt::format("{}", s.samples),
           fmt::format("sampled area {} of {}", n.area(s.sampled_area),
                       n.area_with_units(s.workpiece_area)));
  if (s.tolerance) {
    const ToleranceAreas& t = *s.tolerance;
    const auto share = [&](double area) {
      return fmt::format("{} {}\u00b2, {:.2f} % of the area", n.area(area), n.units,
                         100 * s.share(area));
    };
    stat_row(out, "within tolerance", "", share(t.within));
    stat_row(out, "excess", "", share(t.excess));
    stat_row(out, "gouge", "", share(t.gouge));
  }
  out += "</table>\n";
}

void write_regions(std::string& out, const PartReport& r, const NumberStyle& n) {
  if (!r.statistics.tolerance) return;
  if (r.regions.empty()) {
    out +=
        "<h3>Out-of-tolerance regions</h3>\n<p>None: every sample lies within the "
        "tolerance zone.</p>\n";
    return;
  }
  append(out,
         "<h3>Out-of-tolerance regions: {}</h3>\n<p class=\"ncv-note\">Largest first. Choose a "
         "row to bring the view to the region.</p>\n<div class=\"ncv-regions\"><table>\n"
         "<tr><th class=\"num\">#</th><th>kind</th><th class=\"num\">area ({}\u00b2)</th>"
         "<th class=\"num\">extreme ({})</th><th>at</th></tr>\n",
         r.regions.size(), esc(n.units), esc(n.units));
  for (std::size_t k = 0; k < r.regions.size() && k < kMostRegionRows; ++k) {
    const ErrorRegion& e = r.regions[k];
    append(out,
           "<tr data-region=\"{0}\" tabindex=\"0\"><td class=\"num\">{0}</td>"
           "<td class=\"ncv-{1}\">{1}</td><td class=\"num\">{2}</td><td class=\"num\">{3}</td>"
           "<td>{4}</td></tr>\n",
           k + 1, kind_name(e.kind), n.area(e.area), n.length(e.extreme.value),
           n.point(e.extreme.position));
  }
  out += "</table></div>\n";
  if (r.regions.size() > kMostRegionRows) {
    append(out,
           "<p class=\"ncv-note\">{} more regions are marked in the view and listed in the "
           "regions CSV.</p>\n",
           r.regions.size() - kMostRegionRows);
  }
}

void write_direction(std::string& out, const HtmlDirection& d, std::size_t index) {
  const NumberStyle n = report_number_style(*d.report);
  const PictureText text = picture_text(*d.report);
  append(out, "<section class=\"ncv-direction\" data-view=\"ncv-view-{}\">\n<h2>{}</h2>\n", index,
         esc(d.title));
  write_statistics(out, *d.report, n);
  out +=
      "<h3>The coloured surface</h3>\n<div class=\"ncv-viewer\">\n<div>\n"
      "<div class=\"ncv-tools\"><button class=\"ncv-home\" type=\"button\">Whole part</button>"
      "<button type=\"button\" data-worst=\"0\">Go to the max</button>"
      "<button type=\"button\" data-worst=\"1\">Go to the min</button></div>\n"
      "<div class=\"ncv-canvas\"></div>\n"
      "<div class=\"ncv-readout\">Point at the part to read the error there.</div>\n</div>\n";
  std::ostringstream legend;
  write_legend_svg(legend, d.map, text);
  append(out, "<div class=\"ncv-legend\">{}</div>\n</div>\n", inline_svg(legend.str(), index));
  append(out,
         "<p class=\"ncv-note\">Drag to turn, scroll to zoom, drag with the right button to "
         "move. Yellow markers: the largest and the smallest error; red and blue markers: the "
         "extreme of each excess and gouge region. {}</p>\n",
         esc(describe(d.display)));
  write_regions(out, *d.report, n);
  std::ostringstream histogram;
  write_histogram_svg(histogram, d.report->statistics.histogram,
                      d.report->statistics.tolerance ? d.map.tolerance : std::nullopt, text);
  append(out, "<h3>Histogram</h3>\n<div class=\"ncv-histogram\">{}</div>\n",
         inline_svg(histogram.str(), index));
  const Vec3 center = bounding_box(d.display.mesh.mesh).center();
  append(out, "<script type=\"application/json\" id=\"ncv-view-{}\">{}</script>\n", index,
         script_json(view_json(d, index, center, n)));
  append(out, "<script type=\"application/octet-stream\" id=\"ncv-mesh-{}\">{}</script>\n", index,
         base64(mesh_bytes(d.display.mesh, d.map, center)));
  out += "</section>\n";
}

}  // namespace

std::string html_report(const HtmlReport& report) {
  const Banner verdict = banner_of(report);
  std::string out;
  write_head(out, report, verdict);
  const NumberStyle numbers = report.directions.empty()
                                  ? NumberStyle{}
                                  : report_number_style(*report.directions.front().report);
  write_banner(out, report, verdict, numbers);
  out += "<main>\n";
  write_facts(out, report);
  for (std::size_t k = 0; k < report.directions.size(); ++k) {
    write_direction(out, report.directions[k], k);
  }
  out += "</main>\n<script>\n";
  out += report_viewer_script();
  out += "\n</script>\n</body>\n</html>\n";
  return out;
}

HtmlReport verification_html_report(const VerificationReport& r, std::span<const ColorMap> maps,
                                    std::uint64_t budget) {
  const PartReport& main = r.main;
  const DistanceSet& d = *main.distances;
  const NumberStyle n = report_number_style(main);
  const bool forward = d.direction == Direction::forward;
  HtmlReport report;
  report.part = main.part;
  report.units = main.units;
  report.trace = r.trace;
  report.verdict = r.verdict();
  report.missing_direction = r.missing_direction_reason();
  const HtmlInput sampled{forward ? "workpiece" : "nominal", d.samples.source,
                          hash_hex(d.samples.mesh_hash), d.samples.mesh.triangle_count()};
  const HtmlInput reference{forward ? "nominal" : "workpiece", d.reference.source,
                            hash_hex(d.reference.hash), d.reference.triangles};
  report.inputs = forward ? std::vector<HtmlInput>{sampled, reference}
                          : std::vector<HtmlInput>{reference, sampled};
  const std::optional<ToleranceAreas>& zone = main.statistics.tolerance;
  report.parameters = {
      {"tolerance",
       zone ? fmt::format("[{}, {}] {}", zone->tolerance.lower, zone->tolerance.upper, n.units)
            : std::string("none")},
      {"sampling step",
       fmt::format("{} ({})", n.length_with_units(d.samples.step), d.samples.step_spec)},
      {"sampling scheme", d.samples.scheme == SamplingScheme::all ? "all (paper I)" : "paper-ii"},
      {"directions",
       r.reverse ? "both: workpiece against nominal, nominal against workpiece"
                 : (forward ? "one: workpiece against nominal" : "one: nominal against workpiece")},
      {"sign", d.sign_method},
      {"search", d.search},
      {"units", n.units}};
  if (const std::optional<double> h = r.hausdorff()) {
    report.parameters.push_back({"two-sided Hausdorff distance", n.length_with_units(*h)});
  }
  std::vector<const PartReport*> directions{&main};
  if (r.reverse) directions.push_back(&*r.reverse);
  for (std::size_t k = 0; k < directions.size() && k < maps.size(); ++k) {
    const PartReport& p = *directions[k];
    const DistanceSet& set = *p.distances;
    const std::optional<ToleranceAreas>& t = p.statistics.tolerance;
    report.directions.push_back(
        {set.direction == Direction::forward
             ? "Workpiece against the nominal (the workpiece's samples)"
             : "Nominal against the workpiece (the nominal's samples: a feature the workpiece "
               "lacks shows here)",
         &p, maps[k],
         make_display_mesh(
             {set.samples, set.field.distance, p.sample_region,
              t ? std::optional<Tolerance>(t->tolerance) : std::nullopt, maps[k].range},
             budget / directions.size())});
  }
  return report;
}

}  // namespace ncv
