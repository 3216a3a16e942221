// Logging to standard error (never standard output, which may carry data).
#pragma once

namespace ncv {

enum class Verbosity { quiet, normal, verbose };

// Routes spdlog's default logger to stderr with the "ncverify: " prefix.
void setup_logging(Verbosity verbosity);

}  // namespace ncv
