// ncverify inspect FILE: the header and records of any ncverify file, as text, JSON or CSV.
#include "commands.hpp"
#include "options.hpp"
#include "runners/inspect_runner.hpp"

namespace ncv::cmd {
void add_inspect_command(CLI::App& app, CommandContext&) {
  auto job = std::make_shared<InspectJob>();
  CLI::App* sub = app.add_subcommand("inspect", "Show an ncverify file's header and records");
  sub->add_option("file", job->file, "Samples, grid or distance file (- = stdin)")->required();
  auto* json = sub->add_flag("--json", job->json, "Header and metadata as JSON");
  sub->add_flag("--csv", job->csv, "Records as CSV (one row per record)")->excludes(json);
  add_parsed_option(
      *sub, "--head", job->head,
      [](const std::string& text) {
        return static_cast<std::int64_t>(parse_count(text, 0, kMaxHeadRecords));
      },
      "Only the first N records")
      ->type_name("N");
  sub->add_option("-o,--output", job->output, "Where to write (default: standard output)");
  sub->callback([job] { run_inspect(*job); });
}

}  // namespace ncv::cmd
