// sculpt-cli bench subdivide CONTROL --levels K [--repeat N]: the cost of refinement (the
// precomputation) and of one application of the stencils (the per-frame work).

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "cli/cli_args.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "mesh/topology.h"
#include "subdiv/mj_refiner.h"
#include "util/parallel_for.h"

namespace sculpt::cli {

const char* const kBenchUsage =
    "  bench subdivide CONTROL.json --levels K [--repeat N]\n"
    "      Times subdivide() (median of N runs, default 5) and one application of the level-K\n"
    "      stencils to the control points (median of 51 runs). The last line is\n"
    "      subdivide_ms=<x> apply_ms=<y> cells=<level-K cells> vertices=<level-K vertices>.\n";

namespace {

constexpr OptionSpec kOptions[] = {{"levels", true}, {"repeat", true}, {"help", false}};
constexpr int kApplyRuns = 51;

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double median(std::vector<double> samples) {
  std::sort(samples.begin(), samples.end());
  const size_t n = samples.size();
  return n % 2 == 1 ? samples[n / 2] : 0.5 * (samples[n / 2 - 1] + samples[n / 2]);
}

// Median time of `runs` calls, after one untimed call that sizes buffers and warms caches.
template <typename F>
double medianTime(int runs, F&& body) {
  body();
  std::vector<double> samples;
  for (int i = 0; i < runs; ++i) {
    const Clock::time_point start = Clock::now();
    body();
    samples.push_back(millisecondsSince(start));
  }
  return median(std::move(samples));
}

std::string ms(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", value);
  return text;
}

int benchSubdivide(const CliArgs& args, std::string& file) {
  if (args.positional().size() != 2) {
    throw UsageError("bench subdivide needs exactly one CONTROL file (see --help)");
  }
  const std::string control = args.positional()[1];
  const int levels = args.intValue("levels", 0, 1, kMaxLevels);
  if (!args.has("levels")) throw UsageError("--levels is required");
  const int repeat = args.intValue("repeat", 5, 1, 1000);

  file = control;
  const std::optional<LoadedMesh> loaded = loadValidControlMesh(control);
  if (!loaded) return kExitBadInput;
  const CellComplex& mesh = loaded->mesh;
  const uint64_t estimate = estimateRefinedCells(buildTopology(mesh), levels);
  if (estimate > kMaxEstimatedCells) {
    return printError(control + ": level " + std::to_string(levels) + " would have about " +
                      std::to_string(estimate) + " cells (more than " +
                      std::to_string(kMaxEstimatedCells) + "); use fewer levels");
  }
  std::cout << "file=" << control << " control_cells=" << mesh.numCells()
            << " control_vertices=" << mesh.numVertices() << '\n'
            << "threads=" << workerCount() << " levels=" << levels << " repeat=" << repeat
            << " apply_runs=" << kApplyRuns << '\n';
  std::cout.flush();

  // Precomputation: refinement with stencils, timed as a whole.
  std::optional<Subdivision> result;
  std::vector<double> samples;
  for (int i = 0; i < repeat; ++i) {
    const Clock::time_point start = Clock::now();
    result = subdivide(mesh, levels);
    samples.push_back(millisecondsSince(start));
    if (!result) return printError(control + ": refinement was cancelled");
  }
  const double subdivideMs = median(samples);

  // Per-frame work: d = A p, composed and factored.
  const Points& p = mesh.positions;
  Points d(result->stencils.numRows(), 3);
  const double composedMs = medianTime(kApplyRuns, [&] { result->stencils.apply(p, d); });
  const double chainMs = medianTime(kApplyRuns, [&] { result->chain.apply(p, d); });
  size_t chainEntries = 0;
  for (const StencilTable& level : result->chain.levels()) chainEntries += level.numEntries();

  std::cout << "composed_apply_ms=" << ms(composedMs)
            << " entries=" << result->stencils.numEntries() << " chain_entries=" << chainEntries
            << '\n';
  std::cout << "subdivide_ms=" << ms(subdivideMs) << " apply_ms=" << ms(chainMs)
            << " cells=" << result->finest().numCells()
            << " vertices=" << result->finest().numVertices() << '\n';
  return kExitSuccess;
}

int bench(const CliArgs& args, std::string& file) {
  if (args.has("help")) {
    std::cout << "usage:\n" << kBenchUsage;
    return kExitSuccess;
  }
  if (args.positional().empty()) throw UsageError("bench needs a benchmark name (subdivide)");
  const std::string& name = args.positional()[0];
  if (name == "subdivide") return benchSubdivide(args, file);
  throw UsageError("unknown benchmark '" + name + "' (expected subdivide)");
}

}  // namespace

int runBenchCommand(const std::vector<std::string>& args) {
  std::string file;
  return runGuarded(file, [&] { return bench(CliArgs::parse(args, kOptions), file); });
}

}  // namespace sculpt::cli
