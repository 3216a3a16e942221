#include "option_checks.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>

#include "sampling/sampling_step.hpp"
#include "statistics/tolerance.hpp"
#include "statistics/value_range.hpp"
#include "util/error.hpp"

namespace ncv::cmd {
namespace {

// The parser's own UsageError message becomes the validator's verdict (CLI11 prefixes the
// option's name), so the command line and the library refuse a value in the same words.
template <class Parse>
CLI::Validator refusing(Parse parse) {
  return CLI::Validator(
      [parse](std::string& text) -> std::string {
        try {
          parse(text);
        } catch (const UsageError& e) {
          return e.what();
        }
        return {};
      },
      "");
}

}  // namespace

CLI::Validator valid_step() {
  return refusing([](const std::string& text) { SamplingStep::parse(text); });
}

CLI::Validator valid_zone() {
  return refusing([](const std::string& text) { parse_tolerance(text); });
}

CLI::Validator valid_range() {
  return refusing([](const std::string& text) { parse_value_range(text); });
}

CLI::Validator valid_positive_length() {
  return refusing([](const std::string& text) {
    double value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() ||
        !std::isfinite(value) || !(value > 0)) {
      throw UsageError("'" + text + "' is not a positive length in model units");
    }
  });
}

CLI::Validator valid_count() {
  return refusing([](const std::string& text) {
    std::int64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() || value < 0) {
      throw UsageError("'" + text + "' is not a count (a whole number, 0 or more)");
    }
  });
}

}  // namespace ncv::cmd
