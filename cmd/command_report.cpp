// ncverify report DIST... -o PART.html: the self-contained HTML report of a part
// (runners/html_runner.hpp), the page `run` writes as PART.report.html.
#include "commands.hpp"
#include "option_groups.hpp"
#include "options.hpp"
#include "runners/html_runner.hpp"

namespace ncv::cmd {

void add_report_command(CLI::App& app, CommandContext& context) {
  auto job = std::make_shared<HtmlJob>();
  CLI::App* sub = app.add_subcommand(
      "report",
      "Write the HTML report of a part: verdict, statistics, a 3D view of the coloured "
      "surface, regions and histogram, in one page that opens offline; exit 1 out of "
      "tolerance");
  sub->add_option("distances", job->distances,
                  "Distance file from `distance` (- = stdin), and optionally the same part's "
                  "reverse distance file (`distance --reverse`); or every shard's of each")
      ->required();
  add_samples_file_option(*sub, job->samples);
  add_output_option(*sub, job->output, "HTML file (default: DIST stem + .report.html)");
  add_tolerance_option(
      *sub, job->options.tolerance,
      "Tolerance zone LOWER:UPPER (e.g. -0.05:0.1), or T for ±T; out of it, exit 1");
  add_report_options(*sub, job->options);
  add_one_sided_option(*sub, job->options);
  add_color_map_options(*sub, job->colors);
  sub->add_option("--histogram-svg", job->files.histogram_svg,
                  "Also draw the area-weighted histogram as SVG");
  add_report_file_options(*sub, job->files);
  sub->callback([job, &context] {
    job->output = default_output(job->output, job->distances.front(), ".report.html");
    job->command_line = context.command_line;
    context.exit_status = run_html_report(*job);
  });
}

}  // namespace ncv::cmd
