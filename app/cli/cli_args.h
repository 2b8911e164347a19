#pragma once
// Option parsing for sculpt-cli subcommands: `--opt VALUE`, `--opt=VALUE`, flags, positional
// arguments, `--` to end options. Unknown options are errors, never silently ignored.

#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sculpt::cli {

/// Bad command-line usage; what() is one line without the "error: " prefix.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// One accepted option, named without the leading "--".
struct OptionSpec {
  std::string_view name;
  bool takesValue = false;
  /// Further arguments the option consumes after its value (`--force BOX FX,FY,FZ` has one);
  /// they are appended to the value, separated by single spaces.
  int extraValues = 0;
};

class CliArgs {
 public:
  /// Parses the arguments that follow the subcommand. Throws UsageError.
  static CliArgs parse(std::span<const std::string> args, std::span<const OptionSpec> options);

  bool has(std::string_view name) const;
  /// The last value given for the option, if any.
  std::optional<std::string> value(std::string_view name) const;
  /// Every value given for a repeatable option, in order.
  std::vector<std::string> values(std::string_view name) const;
  /// The value, or UsageError "--name is required".
  std::string requiredValue(std::string_view name) const;
  /// The option as an integer in [min, max], `fallback` when absent. Throws UsageError.
  int intValue(std::string_view name, int fallback, int min, int max) const;

  const std::vector<std::string>& positional() const { return positional_; }

 private:
  std::vector<std::pair<std::string, std::string>> options_;  // (name, value) in command order
  std::vector<std::string> positional_;
};

}  // namespace sculpt::cli
