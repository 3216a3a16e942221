#include "util/logging.hpp"

#include <spdlog/sinks/stdout_sinks.h>
#include <spdlog/spdlog.h>

namespace ncv {

void setup_logging(Verbosity verbosity) {
  auto logger = spdlog::get("ncverify");
  if (!logger) {
    // Thread-safe: run makes its pictures side by side.
    logger = spdlog::stderr_logger_mt("ncverify");
    logger->set_pattern("ncverify: %^%l%$: %v");
    spdlog::set_default_logger(logger);
  }
  switch (verbosity) {
    case Verbosity::quiet:
      logger->set_level(spdlog::level::warn);
      break;
    case Verbosity::normal:
      logger->set_level(spdlog::level::info);
      break;
    case Verbosity::verbose:
      logger->set_level(spdlog::level::debug);
      break;
  }
}

}  // namespace ncv
