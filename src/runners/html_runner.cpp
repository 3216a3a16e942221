#include "runners/html_runner.hpp"

#include <spdlog/spdlog.h>

#include <deque>

#include "files/distance_job.hpp"
#include "render/html_report.hpp"
#include "util/output_file.hpp"

namespace ncv {

std::string html_page(const VerificationReport& report, const ColorizeOptions& colors) {
  ColorizeOptions options = colors;
  const std::optional<ToleranceAreas>& zone = report.main.statistics.tolerance;
  options.tolerance = zone ? std::optional<Tolerance>(zone->tolerance) : std::nullopt;
  std::vector<ColorMap> maps{choose_color_map(*report.main.distances, options)};
  if (report.reverse) maps.push_back(choose_color_map(*report.reverse->distances, options));
  return html_report(verification_html_report(report, maps));
}

int run_html_report(const HtmlJob& job) {
  const PartDistances part = read_part_distances(job.distances, job.samples);
  VerificationReport report =
      make_verification_report(part.main, part.reverse ? &*part.reverse : nullptr, job.options);
  report.trace = traceability(job.command_line);
  OutputFile out(job.output, OutputKind::text);
  std::deque<OutputFile> extras = write_report_files(report.main, job.files);
  out.write(html_page(report, job.colors));
  out.commit();
  for (OutputFile& extra : extras) extra.commit();
  spdlog::info("wrote {}", out.display_name());
  return verdict_status(report);
}

}  // namespace ncv
