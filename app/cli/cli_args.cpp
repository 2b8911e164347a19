#include "cli/cli_args.h"

#include <algorithm>
#include <charconv>

namespace sculpt::cli {

CliArgs CliArgs::parse(std::span<const std::string> args, std::span<const OptionSpec> options) {
  CliArgs result;
  bool optionsEnded = false;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (optionsEnded || arg.size() < 2 || arg[0] != '-') {
      result.positional_.push_back(arg);
      continue;
    }
    if (arg == "--") {
      optionsEnded = true;
      continue;
    }
    if (arg == "-h") {
      result.options_.emplace_back("help", "");
      continue;
    }
    if (arg.rfind("--", 0) != 0) throw UsageError("unknown option '" + arg + "'");
    // Split "--name=value".
    const size_t equals = arg.find('=');
    const std::string name =
        arg.substr(2, equals == std::string::npos ? std::string::npos : equals - 2);
    const auto spec = std::find_if(options.begin(), options.end(),
                                   [&](const OptionSpec& s) { return s.name == name; });
    if (spec == options.end()) throw UsageError("unknown option '--" + name + "'");
    if (!spec->takesValue) {
      if (equals != std::string::npos) throw UsageError("option '--" + name + "' takes no value");
      result.options_.emplace_back(name, "");
    } else {
      std::string value;
      if (equals != std::string::npos) {
        value = arg.substr(equals + 1);
      } else {
        if (i + 1 >= args.size()) throw UsageError("option '--" + name + "' needs a value");
        value = args[++i];
      }
      for (int extra = 0; extra < spec->extraValues; ++extra) {
        if (i + 1 >= args.size())
          throw UsageError("option '--" + name + "' needs " +
                           std::to_string(spec->extraValues + 1) + " values");
        value += ' ' + args[++i];
      }
      result.options_.emplace_back(name, std::move(value));
    }
  }
  return result;
}

bool CliArgs::has(std::string_view name) const {
  return std::any_of(options_.begin(), options_.end(),
                     [&](const auto& option) { return option.first == name; });
}

std::optional<std::string> CliArgs::value(std::string_view name) const {
  for (auto it = options_.rbegin(); it != options_.rend(); ++it) {
    if (it->first == name) return it->second;
  }
  return std::nullopt;
}

std::vector<std::string> CliArgs::values(std::string_view name) const {
  std::vector<std::string> result;
  for (const auto& [key, text] : options_) {
    if (key == name) result.push_back(text);
  }
  return result;
}

std::string CliArgs::requiredValue(std::string_view name) const {
  const auto text = value(name);
  if (!text) throw UsageError("--" + std::string(name) + " is required");
  return *text;
}

int CliArgs::intValue(std::string_view name, int fallback, int min, int max) const {
  const auto text = value(name);
  if (!text) return fallback;
  int result = 0;
  const char* end = text->data() + text->size();
  const auto [ptr, error] = std::from_chars(text->data(), end, result);
  if (error != std::errc() || ptr != end || result < min || result > max) {
    throw UsageError("--" + std::string(name) + " must be an integer from " + std::to_string(min) +
                     " to " + std::to_string(max) + ", got '" + *text + "'");
  }
  return result;
}

}  // namespace sculpt::cli
