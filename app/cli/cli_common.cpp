#include "cli/cli_common.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <new>

#include "cli/cli_args.h"
#include "io/control_mesh_json.h"

namespace sculpt::cli {

GradientScheme gradientSchemeOption(const CliArgs& args) {
  const auto value = args.value("gradients");
  if (!value) return kDefaultGradientScheme;
  const auto scheme = parseGradientScheme(*value);
  if (!scheme)
    throw UsageError("--gradients: unknown scheme '" + *value + "' (expected average or fit)");
  return *scheme;
}

int printError(std::string_view message) {
  // One line, whatever the message holds (file names and messages may carry newlines).
  std::string line = "error: ";
  for (char ch : message) line.push_back(ch == '\n' || ch == '\r' ? ' ' : ch);
  std::cout.flush();
  std::cerr << line << '\n';
  std::cerr.flush();
  return kExitBadInput;
}

int runGuarded(const std::string& file, const std::function<int()>& body) {
  // `file` is read only on failure: callers may set it after parsing their arguments.
  const auto prefix = [&file] { return file.empty() ? std::string() : file + ": "; };
  try {
    return body();
  } catch (const UsageError& error) {
    return printError(error.what());
  } catch (const FileError& error) {
    return printError(error.what());
  } catch (const std::bad_alloc&) {
    return printError(prefix() + "out of memory");
  } catch (const std::exception& error) {
    return printError(prefix() + error.what());
  }
}

bool vertexIdsInRange(const CellComplex& mesh) {
  const uint32_t n = mesh.numVertices();
  const auto below = [n](uint32_t v) { return v < n; };
  return std::all_of(mesh.loopVertices.begin(), mesh.loopVertices.end(), below) &&
         std::all_of(mesh.corners.begin(), mesh.corners.end(), below) &&
         std::all_of(mesh.creases.begin(), mesh.creases.end(),
                     [n](const auto& edge) { return edge[0] < n && edge[1] < n; });
}

size_t countErrors(const std::vector<ValidationIssue>& issues) {
  return static_cast<size_t>(std::count_if(issues.begin(), issues.end(), [](const auto& issue) {
    return issue.severity == ValidationIssue::Severity::Error;
  }));
}

std::string validationFailure(const std::string& path, const std::vector<ValidationIssue>& issues,
                              const std::string& moreHint) {
  const auto first = std::find_if(issues.begin(), issues.end(), [](const auto& issue) {
    return issue.severity == ValidationIssue::Severity::Error;
  });
  if (first == issues.end()) return path + ": valid";
  std::string message = path + ": " + first->message;
  const size_t errors = countErrors(issues);
  if (errors > 1) message += " (and " + std::to_string(errors - 1) + " more; " + moreHint + ")";
  return message;
}

std::optional<LoadedMesh> loadValidControlMesh(const std::string& path) {
  LoadedMesh loaded;
  try {
    loaded.mesh = loadControlMeshJson(path);
  } catch (const FileError& error) {
    printError(error.what());
    return std::nullopt;
  }
  loaded.issues = validate(loaded.mesh);
  if (countErrors(loaded.issues) > 0) {
    printError(validationFailure(path, loaded.issues, "'sculpt-cli info " + path + "' lists them"));
    return std::nullopt;
  }
  return loaded;
}

ProgressReporter stderrProgress() {
  struct State {
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    std::string lastStage;
  };
  auto state = std::make_shared<State>();
  return ProgressReporter([state](double fraction, std::string_view stage) {
    if (stage != state->lastStage) {
      state->lastStage = std::string(stage);
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - state->start).count();
      char line[64];
      std::snprintf(line, sizeof line, "[%7.2f s] %3.0f%% ", seconds, 100.0 * fraction);
      std::cerr << line << stage << '\n';
    }
    return true;
  });
}

std::string lowerExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  return ext;
}

}  // namespace sculpt::cli
