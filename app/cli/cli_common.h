#pragma once
// Shared pieces of the sculpt-cli subcommands: exit codes, one-line error reports, loading and
// validating a control mesh, progress lines, size estimates.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "embed/gradient_scheme.h"
#include "mesh/cell_complex.h"
#include "mesh/topology.h"
#include "mesh/validation.h"
#include "util/progress.h"

namespace sculpt::cli {

inline constexpr int kExitSuccess = 0;
/// Bad input or usage: the message names the file, the element and the problem.
inline constexpr int kExitBadInput = 2;

/// Most levels any subcommand refines (what fits is checked by subdiv/refinement_cost.h).
inline constexpr int kMaxLevels = 6;

class CliArgs;

/// The value of --gradients (average or fit), kDefaultGradientScheme when absent. Throws
/// UsageError for another value.
GradientScheme gradientSchemeOption(const CliArgs& args);

/// Prints "error: <message>" to stderr as exactly one line; returns kExitBadInput.
int printError(std::string_view message);

/// Runs `body`, turning any exception into one error line and kExitBadInput. FileError messages
/// already name their file; others are prefixed with `file` (read at the time of the failure)
/// when it is not empty.
int runGuarded(const std::string& file, const std::function<int()>& body);

/// True when every vertex id in loops, creases and corners is below numVertices() (the
/// precondition of buildTopology).
bool vertexIdsInRange(const CellComplex& mesh);

/// A control mesh that loaded and has no validation errors (warnings are kept).
struct LoadedMesh {
  CellComplex mesh;
  std::vector<ValidationIssue> issues;
};

/// "<path>: <first error>" plus "(and N more; <moreHint>)" when there are more errors.
std::string validationFailure(const std::string& path, const std::vector<ValidationIssue>& issues,
                              const std::string& moreHint);

/// Loads and validates `path`. On failure prints one error line and returns nullopt.
std::optional<LoadedMesh> loadValidControlMesh(const std::string& path);

/// Number of error-severity issues.
size_t countErrors(const std::vector<ValidationIssue>& issues);

/// Prints a line on stderr whenever the reported stage changes, with the elapsed time.
ProgressReporter stderrProgress();

/// The file's extension in lower case (".json"), empty when none.
std::string lowerExtension(const std::filesystem::path& path);

}  // namespace sculpt::cli
