// sculpt-cli bench subdivide CONTROL --levels K [--repeat N]: the cost of refinement (the
// precomputation) and of one application of the stencils (the per-frame work).
// sculpt-cli bench fem CONTROL --levels K [--integrator paper|implicit] [--steps N]: the cost of
// one simulation step under gravity.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <iterator>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "cli/cli_args.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/bench_deform.h"
#include "cli/bench_timing.h"
#include "cli/fem_options.h"
#include "mesh/topology.h"
#include "sim/standard_forms.h"
#include "subdiv/mj_refiner.h"
#include "subdiv/refinement_cost.h"
#include "util/parallel_for.h"

namespace sculpt::cli {

const char* const kBenchUsage =
    "  bench subdivide CONTROL.json --levels K [--repeat N]\n"
    "      Times subdivide() (median of N runs, default 5) and one application of the level-K\n"
    "      stencils to the control points (median of 51 runs). The last line is\n"
    "      subdivide_ms=<x> apply_ms=<y> cells=<level-K cells> vertices=<level-K vertices>.\n"
    "  bench fem CONTROL.json (--levels K | --trilinear) [--integrator paper|implicit]\n"
    "            [--steps N] [--dt S] [other FEM options]\n"
    "      Times Simulator::step() under gravity (0, -9.81, 0; y up) and any --force: the\n"
    "      median of N steps (default 100; integrator implicit, dt 1/60 s) after 3 untimed\n"
    "      warm-up steps. Without --fix the control points of the lowest layer (least rest y)\n"
    "      are fixed. Prints the model setup time, threads, control points and nodes; the last\n"
    "      line is fem_step_ms=<median> elements=<n> tricubic=<n> trilinear=<n> pyramid=<n>\n"
    "      cg_iterations=<mean per timed step>. Exit 1 when a step fails.\n"
    "  bench deform [--vertices N] [--method phong|linear|vertex|attribute]\n"
    "               [--gradients fit|average] [--repeat R]\n"
    "      Built-in scene: a tet lattice of 9261 nodes and N points (default 1000000) on a\n"
    "      bumpy sphere inside it. Times a frame (gradients, per-cell coefficients, every point\n"
    "      in single precision; median of R, default 31); each frame of M is followed by a\n"
    "      linear frame and, for phong and vertex, a frame with the other gradient scheme;\n"
    "      stderr reports the median ratios of the run. Last line: deform_ms=<median per frame>\n"
    "      embed_ms=<precompute> vertices=<N> method=<M> gradients=<S> threads=<T>, and for\n"
    "      phong and vertex <S>_over_<other>=<median ratio per frame>.\n";

namespace {

// Options of bench subdivide; bench fem takes these, the FEM options and its own.
constexpr OptionSpec kOptions[] = {{"levels", true}, {"repeat", true}, {"help", false}};
constexpr OptionSpec kFemBenchOptions[] = {
    {"integrator", true}, {"model", true}, {"steps", true}, {"dt", true}};

// Every option of either benchmark.
std::vector<OptionSpec> allOptions() {
  std::vector<OptionSpec> specs(std::begin(kOptions), std::end(kOptions));
  for (const OptionSpec& spec : kFemOptions)
    if (spec.name != "levels") specs.push_back(spec);
  specs.insert(specs.end(), std::begin(kFemBenchOptions), std::end(kFemBenchOptions));
  specs.insert(specs.end(), std::begin(kBenchDeformOptions), std::end(kBenchDeformOptions));
  return specs;
}

constexpr int kApplyRuns = 51;
constexpr int kWarmupSteps = 3;

using Clock = BenchClock;

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
  if (const std::string refusal = refinementRefusal(buildTopology(mesh), levels, control);
      !refusal.empty())
    return printError(refusal);
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

// Fixes the control points whose rest y is the least (the bottom layer); returns how many.
uint32_t fixLowestLayer(Simulator& simulator) {
  const Points& rest = simulator.model().restControl();
  const double low = rest.col(1).minCoeff();
  const double extent = (rest.colwise().maxCoeff() - rest.colwise().minCoeff()).maxCoeff();
  const double tolerance = 1e-9 * std::max(extent, 1.0);
  const double inf = std::numeric_limits<double>::infinity();
  return simulator.fixInBox(Eigen::AlignedBox3d(Eigen::Vector3d(-inf, low - tolerance, -inf),
                                                Eigen::Vector3d(inf, low + tolerance, inf)));
}

int benchFem(const CliArgs& args, std::string& file) {
  if (args.positional().size() != 2) {
    throw UsageError("bench fem needs exactly one CONTROL file (see --help)");
  }
  if (args.has("repeat"))
    throw UsageError("--repeat applies to bench subdivide only (use --steps)");
  if (!args.has("levels") && !args.has("trilinear"))
    throw UsageError("--levels is required (or --trilinear)");
  const std::string control = args.positional()[1];
  const FemCommandOptions options = parseFemOptions(args);
  SimulationSettings settings = parseIntegratorAndStep(args, false);
  const int steps = args.intValue("steps", 100, 1, 1'000'000);

  file = control;
  const std::optional<LoadedMesh> loaded = loadValidControlMesh(control);
  if (!loaded) return kExitBadInput;
  const CellComplex& mesh = loaded->mesh;
  // buildFemModel below refuses a level that would not fit before it allocates.
  std::cout << "file=" << control << " control_cells=" << mesh.numCells()
            << " control_vertices=" << mesh.numVertices() << '\n';
  std::cout.flush();

  const Clock::time_point setupStart = Clock::now();
  std::optional<FemModel> model = buildFemModel(mesh, options.setup, control);
  if (!model) return kExitBadInput;
  const double setupMs = millisecondsSince(setupStart);

  Simulator simulator(*model);
  if (const std::string problem = simulator.setSettings(settings); !problem.empty())
    throw UsageError(problem);
  applyConstraintsAndForces(simulator, options);
  const uint32_t fixed =
      options.fixed.empty()
          ? fixLowestLayer(simulator)
          : static_cast<uint32_t>(
                std::count(simulator.fixedMask().begin(), simulator.fixedMask().end(), uint8_t{1}));
  simulator.addLoad(std::make_unique<GravityForm>(*model, Eigen::Vector3d(0.0, -9.81, 0.0)));

  const ElementCounts counts = model->mesh().counts();
  std::cout << "threads=" << workerCount() << " levels="
            << (options.setup.trilinear ? std::string("trilinear")
                                        : std::to_string(options.setup.level))
            << " integrator=" << integratorName(settings.integrator) << " dt=" << settings.timeStep
            << " steps=" << steps << " warmup=" << kWarmupSteps << '\n'
            << "setup_ms=" << ms(setupMs) << " control_points=" << model->numControlPoints()
            << " nodes=" << model->numNodes() << " fixed=" << fixed << '\n';
  std::cout.flush();

  int failures = 0;
  auto step = [&] {
    const StepReport report = simulator.step();
    if (!report.ok || !report.message.empty()) {
      if (failures == 0) std::cerr << "bench fem: " << report.message << '\n';
      ++failures;
    }
    return report;
  };
  for (int i = 0; i < kWarmupSteps; ++i) step();
  std::vector<double> samples;
  long long iterations = 0;
  bool failed = false;
  for (int i = 0; i < steps; ++i) {
    const Clock::time_point start = Clock::now();
    const StepReport report = step();
    samples.push_back(millisecondsSince(start));
    iterations += report.iterations;
    failed = failed || !report.ok;
  }
  if (failures > 1)
    std::cerr << "bench fem: " << failures << " of " << kWarmupSteps + steps
              << " steps needed sub-steps or failed\n";

  char mean[32];
  std::snprintf(mean, sizeof mean, "%.1f", static_cast<double>(iterations) / steps);
  std::cout << "fem_step_ms=" << ms(median(std::move(samples))) << " elements=" << counts.total()
            << " tricubic=" << counts.tricubic << " trilinear=" << counts.trilinear
            << " pyramid=" << counts.pyramid << " cg_iterations=" << mean << '\n';
  return failed ? 1 : kExitSuccess;
}

int bench(const CliArgs& args, std::string& file) {
  if (args.has("help")) {
    std::cout << "usage:\n"
              << kBenchUsage << "      FEM options (bench fem requires --levels or --trilinear):\n"
              << kFemOptionsUsage;
    return kExitSuccess;
  }
  if (args.positional().empty())
    throw UsageError("bench needs a benchmark name (subdivide, fem or deform)");
  const std::string& name = args.positional()[0];
  if (name == "fem") return benchFem(args, file);
  if (name == "deform") return benchDeform(args);
  if (name == "subdivide") {
    for (const OptionSpec& spec : allOptions()) {
      if (args.has(spec.name) && spec.name != "levels" && spec.name != "repeat" &&
          spec.name != "help")
        throw UsageError("--" + std::string(spec.name) + " applies to bench fem only");
    }
    return benchSubdivide(args, file);
  }
  throw UsageError("unknown benchmark '" + name + "' (expected subdivide, fem or deform)");
}

}  // namespace

int runBenchCommand(const std::vector<std::string>& args) {
  std::string file;
  return runGuarded(file, [&] { return bench(CliArgs::parse(args, allOptions()), file); });
}

}  // namespace sculpt::cli
