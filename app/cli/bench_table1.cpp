// sculpt-cli bench table1 [--steps N] [--models DIR]: each model of the paper's Table 1 at the
// subdivision level whose element count is nearest the paper's, stepped under gravity with both
// integrators, printed as one Markdown table beside the paper's figures.

#include "cli/bench_table1.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "cli/bench_fem.h"
#include "cli/cli_args.h"
#include "cli/cli_common.h"
#include "cli/fem_options.h"
#include "mesh/topology.h"
#include "sim/standard_forms.h"
#include "subdiv/mj_refiner.h"
#include "subdiv/refinement_cost.h"
#include "subdiv/regularity.h"
#include "util/parallel_for.h"

namespace sculpt::cli {

const char* const kBenchTable1Usage =
    "  bench table1 [--steps N] [--models DIR]\n"
    "      The paper's Table 1 beside this build: each of its eight models (DIR, default\n"
    "      assets/table1/ of the source tree) at the level 0-3 whose element count is nearest\n"
    "      the paper's (0: trilinear on the control cells), the lowest layer fixed, under\n"
    "      gravity; the median of N steps (default 30, after warm-up) of each integrator,\n"
    "      paper and implicit. Prints a Markdown table; the last line is models=8\n"
    "      min_speedup_paper=<x> min_speedup_implicit=<x> (the least of our FPS over the\n"
    "      paper's). Exit 1 when a step fails.\n";

namespace {

// A row of the paper's Table 1 (2.8 GHz Pentium 4) and the file of our model of it.
struct PaperRow {
  const char* model;
  const char* file;
  uint32_t cells, elements;
  double fps, mspi;
  int be, le, pe;  // % of tricubic B-spline, trilinear and pyramid elements
};

constexpr PaperRow kPaperTable[] = {
    {"Soccer player", "soccer-player.json", 24, 1536, 7.4, 135, 24, 76, 0},
    {"Sea monster", "sea-monster.json", 38, 320, 21.3, 47, 94, 3, 4},
    {"3^3 block", "block3.json", 27, 1728, 3.2, 310, 58, 42, 0},
    {"Chair", "chair.json", 76, 984, 11.1, 90, 68, 3, 29},
    {"4^3 block", "block4.json", 64, 296, 11.9, 84, 58, 33, 0},
    {"Head", "head.json", 123, 1241, 9.1, 110, 82, 1, 17},
    {"Bridge", "bridge.json", 150, 1200, 4.7, 213, 95, 5, 0},
    {"Nozzle", "nozzle.json", 99, 792, 13.3, 75, 100, 0, 0},
};

constexpr int kMaxLevel = 3;
constexpr int kDefaultSteps = 30;

std::string fixed(double value, int decimals) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

std::string percent(uint32_t part, uint32_t total) {
  return fixed(total == 0 ? 0.0 : 100.0 * part / total, 0) + "%";
}

// assets/table1 under the working folder, else under the source tree, which holds the build
// folder with its bin/ (build-x/bin/sculpt-cli).
std::filesystem::path defaultModels() {
  namespace fs = std::filesystem;
  const fs::path relative = fs::path("assets") / "table1";
  std::error_code ec;
  if (fs::is_directory(relative, ec)) return relative;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path source = exe.parent_path().parent_path().parent_path() / relative;
    if (fs::is_directory(source, ec)) return source;
  }
  throw UsageError("no assets/table1 here or in the source tree (give --models DIR)");
}

// The elements FemMesh builds on a level (tricubic only for K >= 1): a regular cell gives a
// tricubic one, another hexahedron a trilinear one, any other cell a pyramid per face.
ElementCounts countElements(const Topology& topology, bool tricubic) {
  ElementCounts counts;
  const std::vector<CellRegularity> regularity = classifyCells(topology);
  for (uint32_t c = 0; c < topology.numCells(); ++c) {
    if (tricubic && regularity[c] == CellRegularity::Regular) {
      ++counts.tricubic;
    } else if (topology.cellFaces.rowSize(c) == 6 && topology.cellVertices.rowSize(c) == 8) {
      ++counts.trilinear;
    } else {
      counts.pyramid += topology.cellFaces.rowSize(c);
    }
  }
  return counts;
}

// The level 0..kMaxLevel whose element count is nearest `target` (the lower on a tie).
int nearestLevel(const CellComplex& mesh, uint32_t target) {
  const Topology topology = buildTopology(mesh);
  // Every level-K cell is at least one element, so no level past the first whose cells reach
  // the target can be nearer: refine no further than that.
  int top = 1;
  while (top < kMaxLevel && estimateRefinementCost(topology, top).cells < target) ++top;
  const std::optional<Subdivision> levels = subdivide(mesh, top);
  if (!levels) throw std::runtime_error("refinement was cancelled");
  int best = 0;
  auto distance = [target](uint32_t count) {
    return std::abs(static_cast<int64_t>(count) - static_cast<int64_t>(target));
  };
  int64_t bestDistance = distance(countElements(topology, false).total());
  for (int level = 1; level <= top; ++level) {
    const int64_t d = distance(countElements(levels->topologies[level], true).total());
    if (d < bestDistance) {
      best = level;
      bestDistance = d;
    }
  }
  return best;
}


struct Measured {
  ElementCounts counts;
  FemBenchFigures figures;
};

// A fresh model and simulator per integrator, so that neither run inherits the other's state.
std::optional<Measured> measure(const CellComplex& mesh, const FemSetup& setup,
                                Integrator integrator, int steps, const std::string& file) {
  std::optional<FemModel> model = buildFemModel(mesh, setup, file);
  if (!model) return std::nullopt;
  Simulator simulator(*model);
  SimulationSettings settings;
  settings.integrator = integrator;
  if (const std::string problem = simulator.setSettings(settings); !problem.empty())
    throw std::runtime_error(problem);
  fixLowestLayer(simulator);
  simulator.addLoad(std::make_unique<GravityForm>(*model, Eigen::Vector3d(0.0, -9.81, 0.0)));
  FemBenchOptions options;
  options.steps = steps;
  Measured result{model->mesh().counts(), runFemBench(simulator, options, std::cerr)};
  return result;
}

constexpr OptionSpec kOptions[] = {{"steps", true}, {"models", true}, {"help", false}};

int benchTable1(const CliArgs& args, std::string& file) {
  if (args.has("help")) {
    std::cout << "usage:\n" << kBenchTable1Usage;
    return kExitSuccess;
  }
  if (args.positional().size() != 1)
    throw UsageError("bench table1 takes no file (give the models' folder with --models DIR)");
  const int steps = args.intValue("steps", kDefaultSteps, 1, 100'000);
  const std::filesystem::path dir =
      args.has("models") ? std::filesystem::path(*args.value("models")) : defaultModels();

  std::cout << "Left: McDonnell & Qin 2007, Table 1 (2.8 GHz Pentium 4). Right: this build, "
            << workerCount() << " threads, the median of " << steps
            << " steps after warm-up (dt 1/60 s, gravity, lowest layer fixed), for the paper's "
               "integrator and the implicit one; x = our FPS / the paper's.\n\n"
            << "| Model | #CC | #FE | FPS | MSPI | %BE | %LE | %PE | our #CC | our #FE | level "
               "| our %BE | our %LE | our %PE | paper ms | paper FPS | paper x | implicit ms "
               "| implicit FPS | implicit x |\n"
            << "|---|";
  for (int column = 1; column < 20; ++column) std::cout << "---:|";  // numbers align right
  std::cout << '\n';
  std::cout.flush();

  double minSpeedup[2] = {std::numeric_limits<double>::infinity(),
                          std::numeric_limits<double>::infinity()};
  bool failed = false;
  for (const PaperRow& paper : kPaperTable) {
    file = (dir / paper.file).string();
    const std::optional<LoadedMesh> loaded = loadValidControlMesh(file);
    if (!loaded) return kExitBadInput;
    const CellComplex& mesh = loaded->mesh;
    FemSetup setup;
    const int level = nearestLevel(mesh, paper.elements);
    setup.level = std::max(level, 1);
    setup.trilinear = level == 0;

    std::string timings;
    ElementCounts counts;
    for (const Integrator integrator : {Integrator::Paper, Integrator::Implicit}) {
      const std::optional<Measured> run = measure(mesh, setup, integrator, steps, file);
      if (!run) return kExitBadInput;
      counts = run->counts;
      const double ms = run->figures.medianStepMs;
      const double fps = 1000.0 / ms;
      const double speedup = fps / paper.fps;
      double& least = minSpeedup[integrator == Integrator::Paper ? 0 : 1];
      least = std::min(least, speedup);
      failed = failed || run->figures.failed;
      timings += " " + fixed(ms, 3) + " | " + fixed(fps, 1) + " | " + fixed(speedup, 1) + " |";
    }
    const uint32_t total = counts.total();
    std::cout << "| " << paper.model << " | " << paper.cells << " | " << paper.elements << " | "
              << fixed(paper.fps, 1) << " | " << fixed(paper.mspi, 0) << " | " << paper.be
              << "% | " << paper.le << "% | " << paper.pe << "% | " << mesh.numCells() << " | "
              << total << " | " << level << " | " << percent(counts.tricubic, total) << " | "
              << percent(counts.trilinear, total) << " | " << percent(counts.pyramid, total)
              << " |" << timings << '\n';
    std::cout.flush();
  }
  std::cout << "\nmodels=" << std::size(kPaperTable)
            << " min_speedup_paper=" << fixed(minSpeedup[0], 2)
            << " min_speedup_implicit=" << fixed(minSpeedup[1], 2) << '\n';
  return failed ? 1 : kExitSuccess;
}

}  // namespace

int runBenchTable1(const std::vector<std::string>& args) {
  std::string file;
  return runGuarded(file, [&] { return benchTable1(CliArgs::parse(args, kOptions), file); });
}

}  // namespace sculpt::cli
