// ncgen: generates the test data of ncverify (see tools/ncgen/README.md): a CAD-like mould core,
// its workpieces after simulated roughing, semi-finishing and finishing, and analytic boxes.
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <exception>
#include <stdexcept>

#include "commands.hpp"

int main(int argc, char** argv) {
  using namespace ncv::gen::app;
  CLI::App app{"ncgen: nominal parts and NC-milled workpieces for testing ncverify"};
  app.require_subcommand(1);
  app.fallthrough();
  GlobalOptions global;
  bool quiet = false;
  app.add_option("--seed", global.seed, "Seed of the mould core's freeform shape")
      ->capture_default_str();
  app.add_flag("-q,--quiet", quiet, "Only warnings and errors on standard error");

  add_nominal_command(app, global);
  add_workpiece_command(app, global);
  add_box_command(app);
  add_scallop_command(app);
  add_all_command(app, global);

  // Standard output stays free for data; progress goes to standard error.
  app.parse_complete_callback([&] {
    auto logger = spdlog::stderr_color_mt("ncgen");
    logger->set_pattern("ncgen: %v");
    logger->set_level(quiet ? spdlog::level::warn : spdlog::level::info);
    spdlog::set_default_logger(logger);
  });
  // Exit statuses: 0 done, 1 failed (e.g. cannot write), 2 bad usage.
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  } catch (const std::invalid_argument& e) {
    spdlog::error("{}", e.what());
    return 2;
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return 1;
  }
  return 0;
}
