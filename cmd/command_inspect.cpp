// ncverify inspect FILE: the header and records of any ncverify file, as text, JSON or CSV.
#include <charconv>

#include "commands.hpp"
#include "options.hpp"
#include "runners/inspect_runner.hpp"

namespace ncv::cmd {
namespace {

std::int64_t parse_count(const std::string& text) {
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() || value < 0) {
    throw UsageError("'" + text + "' is not a count (a whole number, 0 or more)");
  }
  return value;
}

}  // namespace

void add_inspect_command(CLI::App& app, CommandContext&) {
  auto job = std::make_shared<InspectJob>();
  CLI::App* sub = app.add_subcommand("inspect", "Show an ncverify file's header and records");
  sub->add_option("file", job->file, "Samples, grid or distance file (- = stdin)")->required();
  auto* json = sub->add_flag("--json", job->json, "Header and metadata as JSON");
  sub->add_flag("--csv", job->csv, "Records as CSV (one row per record)")->excludes(json);
  add_parsed_option(*sub, "--head", job->head, parse_count, "Only the first N records");
  sub->add_option("-o,--output", job->output, "Where to write (default: standard output)");
  sub->callback([job] { run_inspect(*job); });
}

}  // namespace ncv::cmd
