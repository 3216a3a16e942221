#include "runners/html_runner.hpp"

#include <spdlog/spdlog.h>

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
  const int status = write_part_report(
      job.distances, job.samples, job.options, job.command_line, job.output, job.files,
      [&job](const VerificationReport& report) { return html_page(report, job.colors); });
  spdlog::info("wrote {}", job.output);
  return status;
}

}  // namespace ncv
