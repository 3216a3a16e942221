// ncverify run WORKPIECE NOMINAL: sample, grid-build, distance, stats and colorize in one
// go, keeping every intermediate file in an output folder.
#include "commands.hpp"
#include "option_groups.hpp"
#include "options.hpp"
#include "runners/verify_runner.hpp"

namespace ncv::cmd {

void add_run_command(CLI::App& app, CommandContext& context) {
  auto job = std::make_shared<RunJob>();
  VerifyOptions& options = job->options;
  CLI::App* sub = app.add_subcommand(
      "run", "Verify WORKPIECE against NOMINAL in one go (all steps, intermediates kept)");
  sub->add_option("workpiece", job->workpiece, "Machined workpiece mesh")->required();
  sub->add_option("nominal", job->nominal, "Nominal part mesh")->required();
  sub->add_option("-d,--dir", job->folder, "Output folder (default: WORKPIECE stem + .ncverify)");
  add_sample_options(*sub, options.sampling);
  add_grid_options(*sub, options.grid);
  add_distance_options(*sub, options.distance);
  add_tolerance_option(
      *sub, options.report.tolerance,
      "Tolerance zone LOWER:UPPER (e.g. -0.05:0.1), or T for ±T; out of it, exit 1");
  add_report_options(*sub, options.report);
  sub->add_option("--histogram-svg", job->histogram_svg,
                  "Where to draw the histogram (default: in the output folder)");
  add_colorize_options(*sub, options.colorize);
  sub->add_option("--legend", job->legend_svg,
                  "Where to write the colour bar (default: in the output folder)");
  sub->add_flag(
      "--one-sided", [job](std::int64_t) { job->options.two_sided = false; },
      "Measure the workpiece against the nominal only (not the nominal against the "
      "workpiece: a feature the workpiece lacks can then pass)");
  add_enum_option(*sub, "--format", job->format, kReportFormatNames, "Report on stdout");
  add_enum_option(*sub, "--keep", job->keep, kKeepNames,
                  "What stays in the output folder: every step's file, the reports and "
                  "pictures only, or nothing (the report on stdout)");
  sub->add_option("--timings", job->timings,
                  "Also write each phase's wall time and the peak memory as JSON (benchmarks)");
  sub->callback([job, &context] {
    job->command_line = context.command_line;
    context.exit_status = run_verification(*job);
  });
}

}  // namespace ncv::cmd
