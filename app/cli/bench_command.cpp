// sculpt-cli bench subdivide CONTROL --levels K [--repeat N]: the cost of refinement (the
// precomputation) and of one application of the stencils (the per-frame work).
// sculpt-cli bench fem CONTROL|SCENE [--levels K] [--integrator paper|implicit] [--steps N]
// [--paint-every N] [--pin-every N]: the cost of one simulation step (cli/bench_fem.h).

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "cli/cli_args.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/bench_deform.h"
#include "cli/bench_fem.h"
#include "cli/bench_table1.h"
#include "cli/bench_timing.h"
#include "cli/fem_options.h"
#include "mesh/topology.h"
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
    "            [--steps N] [--dt S] [--paint-every N [--paint-field youngs|density]]\n"
    "            [--paint-from K] [--pin-every N] [--fresh-factor] [--as-window] [--trace]\n"
    "            [other FEM options]\n"
    "  bench fem SCENE [--levels K] [--cage N] [--integrator paper|implicit] [--model M]\n"
    "            [--dt S] [--steps N] [--paint-every N [--paint-field youngs|density]]\n"
    "            [--paint-from K] [--pin-every N] [--fresh-factor] [--as-window] [--trace]\n"
    "      Times Simulator::step(): the first step (with the preconditioner's first\n"
    "      factorisation), 3 untimed warm-up steps, then N measured steps (default 100;\n"
    "      integrator implicit, dt 1/60 s), and one elastic force evaluation before each\n"
    "      measured step (their median is elastic_pass_ms).\n"
    "      CONTROL.json is under gravity (0, -9.81, 0; y up) and any --force; without --fix the\n"
    "      control points of the lowest layer (least rest y) are fixed. SCENE is what simulate\n"
    "      takes (a surface caged as the window cages it, a .sculpt project, or default) with\n"
    "      its own pins, loads and settings; its build takes the first step. --paint-every N\n"
    "      paints a stiffness dab (radius one control cell, E alternately 10x and 0.1x the\n"
    "      initial one, centres visiting the control cells) before every N-th warm-up and\n"
    "      measured step, outside the timing, as the paint tool does (--paint-field density:\n"
    "      density dabs, 10x and 0.1x, instead); a line dabs=<measured>\n"
    "      warmup_dabs=<n> dab_radius=<m> painted_samples=<n> follows. --paint-from K starts\n"
    "      the dabs at the K-th measured step instead (none in the warm-up), from the factors\n"
    "      a solid that stood still has by then. --pin-every N pins the\n"
    "      control points in the top quarter of the solid (rest y) that nothing else pins\n"
    "      before every N-th warm-up and measured step, and releases them at the next, as the\n"
    "      pin tool holds and lets go; a line pin_edits=<measured> warmup_pin_edits=<n>\n"
    "      pinned_points=<n> follows. --fresh-factor refactors the preconditioner after each\n"
    "      dab or pin edit, outside the timing: the steps' cost without the factor's age, for\n"
    "      comparison. --as-window takes the preconditioner's factors made\n"
    "      on a worker thread when they are ready, never waiting, as the window does (the\n"
    "      steps are then not reproducible). --trace writes step=<k> ms=<x> cg_iterations=<n>\n"
    "      elastic_pass_ms=<y> barrier_elements=<elements below the inversion barrier's\n"
    "      threshold> factorizations=<preconditioner factors so far> extensions=<factors\n"
    "      extended to points released from a pin so far> to stderr for each measured step.\n"
    "      Prints the setup time, threads, control points and nodes, then the heap\n"
    "      (allocator=<glibc|sanitizer> huge_page_heap=<1 if in huge pages, docs/memory.md>\n"
    "      huge_pages_mb=<in use now> peak_rss_mb=<peak resident memory>); the last line is\n"
    "      fem_step_ms=<median>\n"
    "      elements=<n> tricubic=<n> trilinear=<n> pyramid=<n> cg_iterations=<mean per\n"
    "      measured step> elastic_pass_ms=<median> step_passes=<fem_step_ms/elastic_pass_ms>\n"
    "      first_step_ms=<ms> step_p99_ms=<nearest-rank 99th percentile> step_max_ms=<ms>.\n"
    "      Exit 1 when a measured step fails.\n"
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

// Every option of either benchmark.
std::vector<OptionSpec> allOptions() {
  std::vector<OptionSpec> specs(std::begin(kOptions), std::end(kOptions));
  for (const OptionSpec& spec : kFemOptions)
    if (spec.name != "levels") specs.push_back(spec);
  specs.insert(specs.end(), kFemBenchOptions.begin(), kFemBenchOptions.end());
  specs.insert(specs.end(), std::begin(kBenchDeformOptions), std::end(kBenchDeformOptions));
  return specs;
}

constexpr int kApplyRuns = 51;

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

int bench(const CliArgs& args, std::string& file) {
  if (args.has("help")) {
    std::cout << "usage:\n"
              << kBenchUsage << kBenchTable1Usage
              << "      FEM options (bench fem requires --levels or --trilinear):\n"
              << kFemOptionsUsage;
    return kExitSuccess;
  }
  if (args.positional().empty())
    throw UsageError("bench needs a benchmark name (subdivide, fem or deform)");
  const std::string& name = args.positional()[0];
  if (name == "fem") return benchFemCommand(args, file);
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
  if (!args.empty() && args[0] == "table1") return runBenchTable1(args);  // its own options
  std::string file;
  return runGuarded(file, [&] { return bench(CliArgs::parse(args, allOptions()), file); });
}

}  // namespace sculpt::cli
