#include "parse_errors.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <regex>

namespace ncv::cmd {
namespace {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// The candidate nearest to `word`, when it is near enough to be what was meant: a prefix of
// it, or within a third of its length in edits (at least 2).
std::optional<std::string> nearest(const std::string& word,
                                   const std::vector<std::string>& candidates) {
  if (word.size() <= 2) return std::nullopt;  // "-x": any one-letter option is as near
  std::optional<std::string> best;
  std::size_t best_distance = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const std::string& candidate : candidates) {
    const std::size_t d = candidate.rfind(word, 0) == 0 ? 1 : edit_distance(word, candidate);
    if (d < best_distance) {
      best_distance = d;
      best = candidate;
    }
  }
  return best;
}

std::string suggestion(const std::optional<std::string>& near) {
  return near ? fmt::format("; did you mean '{}'?", *near) : std::string();
}

std::vector<std::string> subcommand_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    names.push_back(sub->get_name());
  return names;
}

// Every spelling of every option of `app`: "--tol", "-t".
std::vector<std::string> option_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* option : app.get_options()) {
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
    for (const std::string& name : option->get_snames()) names.push_back("-" + name);
  }
  return names;
}

bool takes_value(const CLI::App& app, const std::string& name) {
  const CLI::Option* option = app.get_option_no_throw(name);
  return option && option->get_expected_min() > 0;
}

// The subcommand the user chose, if CLI11 got that far.
const CLI::App* chosen_subcommand(const CLI::App& app) {
  const std::vector<const CLI::App*> chosen =
      app.get_subcommands([](const CLI::App* sub) { return sub->parsed(); });
  return chosen.empty() ? nullptr : chosen.front();
}

// Options in `args` that neither the app nor `sub` knows, as typed (without "=value").
std::vector<std::string> unknown_options(const CLI::App& app, const CLI::App* sub,
                                         const std::vector<std::string>& args) {
  std::vector<std::string> unknown;
  for (const std::string& arg : args) {
    if (arg == "--") break;
    if (arg.size() < 2 || arg[0] != '-' || std::isdigit(static_cast<unsigned char>(arg[1])) ||
        arg[1] == '.') {
      continue;  // a value, standard input, or a negative number
    }
    const std::string name = arg.substr(0, arg.find('='));
    const std::string probe = name.rfind("--", 0) == 0 ? name : name.substr(0, 2);
    if (app.get_option_no_throw(probe) || (sub && sub->get_option_no_throw(probe))) continue;
    unknown.push_back(name);
  }
  return unknown;
}

}  // namespace

std::optional<std::string> unknown_command(const CLI::App& app,
                                           const std::vector<std::string>& args) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg.empty() || arg[0] == '-') {
      // A global option's separate value is not the command.
      if (arg.find('=') == std::string::npos && takes_value(app, arg)) ++i;
      continue;
    }
    const std::vector<std::string> names = subcommand_names(app);
    if (std::find(names.begin(), names.end(), arg) != names.end()) return std::nullopt;
    return fmt::format("unknown command '{}'{}", arg, suggestion(nearest(arg, names)));
  }
  return std::nullopt;
}

std::string parse_error_message(const CLI::ParseError& error, const CLI::App& app,
                                const std::vector<std::string>& args) {
  const CLI::App* sub = chosen_subcommand(app);
  if (dynamic_cast<const CLI::ExtrasError*>(&error)) {
    const std::vector<std::string> unknown = unknown_options(app, sub, args);
    if (!unknown.empty()) {
      std::vector<std::string> names = option_names(app);
      if (sub) {
        const std::vector<std::string> own = option_names(*sub);
        names.insert(names.end(), own.begin(), own.end());
      }
      return fmt::format("unknown option '{}'{}{}", unknown.front(),
                         sub ? " for " + sub->get_name() : std::string(),
                         suggestion(nearest(unknown.front(), names)));
    }
  }
  // "--tol: 1 required TEXT missing": a value-taking option given last, without its value.
  static const std::regex missing(R"(^(\S+): \d+ required \S+ missing$)");
  std::smatch match;
  const std::string what = error.what();
  if (std::regex_match(what, match, missing)) return match[1].str() + " needs a value";
  return what;
}

}  // namespace ncv::cmd
