#include "cli/bench_fem.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include "allocator/program_allocator.h"
#include "cli/bench_timing.h"
#include "cli/cli_common.h"
#include "cli/fem_options.h"
#include "cli/scene_options.h"
#include "scene/scene_physics.h"
#include "sim/standard_forms.h"
#include "tools/strokes.h"
#include "tools/tool.h"
#include "util/parallel_for.h"

namespace sculpt::cli {

const std::vector<OptionSpec> kFemBenchOptions = {
    {"integrator", true}, {"model", true},       {"steps", true},
    {"dt", true},         {"paint-every", true}, {"paint-from", true}, {"cage", true},
    {"paint-field", true}, {"pin-every", true}, {"fresh-factor", false}, {"as-window", false},
    {"trace", false}};

namespace {

using Clock = BenchClock;

constexpr double kStiffer = 10.0, kSofter = 0.1;

std::string ms(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", value);
  return text;
}

// The nearest-rank percentile: the smallest sample with at least p% of them at or below it.
double percentile(std::vector<double> samples, double p) {
  std::sort(samples.begin(), samples.end());
  const double rank = std::ceil(p / 100.0 * double(samples.size()));
  const size_t index = static_cast<size_t>(std::clamp(rank, 1.0, double(samples.size()))) - 1;
  return samples[index];
}

// The mean of each control cell's distinct rest vertices: a point inside the solid, even where
// the solid is not convex.
std::vector<Eigen::Vector3d> controlCellCentres(const FemModel& model) {
  const CellComplex& control = model.control();
  std::vector<Eigen::Vector3d> centres;
  std::vector<uint32_t> vertices;
  for (uint32_t c = 0; c < control.numCells(); ++c) {
    vertices.clear();
    for (uint32_t j = 0; j < control.numFacesOfCell(c); ++j)
      for (const uint32_t v : control.cellFace(c, j)) vertices.push_back(v);
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const uint32_t v : vertices) sum += control.positions.row(v).transpose();
    centres.push_back(sum / double(std::max<size_t>(vertices.size(), 1)));
  }
  return centres;
}

// A stride near the golden section of n, coprime with n: k * stride mod n visits every cell
// once per n dabs and jumps across the solid between dabs.
uint32_t cellStride(uint32_t n) {
  if (n <= 2) return 1;
  uint32_t stride = std::max<uint32_t>(1, static_cast<uint32_t>(0.618034 * n));
  while (std::gcd(stride, n) != 1) --stride;
  return stride;
}

// Stiffness (or density) dabs through the paint tool's stroke (the session script's paint events
// use the same), on a context over the bare simulator.
class DabPainter {
 public:
  DabPainter(Simulator& simulator, bool density)
      : density_(density),
        context_(simulator),
        centres_(controlCellCentres(simulator.model())),
        stride_(cellStride(static_cast<uint32_t>(centres_.size()))),
        radius_(controlCellSize(simulator.model())),
        base_(simulator.model().setup().material) {}

  double radius() const { return radius_; }
  long samplesPainted() const { return painted_; }

  void paintNext() {
    PaintStroke::Settings settings;
    settings.brush.radius = radius_;
    settings.brush.target = base_;
    const double factor = dabs_ % 2 == 0 ? kStiffer : kSofter;
    if (density_) {
      settings.brush.target.density = base_.density * factor;
      settings.brush.fields = FemModel::MaterialFields{true, false, false, false};
    } else {
      settings.brush.target.youngs = base_.youngs * factor;
      settings.brush.fields = FemModel::MaterialFields{false, false, true, false};
    }
    const size_t cell = (dabs_ * stride_ + centres_.size() / 2) % centres_.size();
    ToolInput input;
    input.restPoint = centres_[cell];
    PaintStroke stroke(settings);
    stroke.begin(context_, input);
    stroke.end(context_, input);
    painted_ += stroke.samplesPainted();
    ++dabs_;
  }

 private:
  bool density_;
  SimulatorToolContext context_;
  std::vector<Eigen::Vector3d> centres_;
  size_t stride_;
  double radius_;
  Material base_;
  size_t dabs_ = 0;
  long painted_ = 0;
};

// A pin on the control points in the top quarter of the solid (by rest y) that are free at the
// start, as the pin tool holds a region: made at the first edit, released at the next, and so on.
class PinToggler {
 public:
  explicit PinToggler(Simulator& simulator) : simulator_(simulator) {
    const Points& rest = simulator.model().restControl();
    if (rest.rows() == 0) return;
    const double low = rest.col(1).minCoeff(), high = rest.col(1).maxCoeff();
    const double threshold = high - 0.25 * (high - low);
    for (Eigen::Index p = 0; p < rest.rows(); ++p)
      if (rest(p, 1) >= threshold && !simulator.fixedMask()[size_t(p)])
        points_.push_back(uint32_t(p));
  }
  uint32_t points() const { return uint32_t(points_.size()); }
  void toggle() {
    pinned_ = !pinned_;
    for (const uint32_t p : points_) simulator_.setFixed(p, pinned_);
  }

 private:
  Simulator& simulator_;
  std::vector<uint32_t> points_;
  bool pinned_ = false;
};

// Times elastic force evaluations at the simulator's current positions, as the step's first pass
// does them, without changing what the next step starts from (the rotations are its warm start).
class ElasticPassTimer {
 public:
  explicit ElasticPassTimer(Simulator& simulator)
      : simulator_(simulator), elastic_(simulator.model(), simulator.settings().corotated) {}

  // The wall time of one pass (ms).
  double timeOnePass() {
    FemModel& model = simulator_.model();
    const ElasticKernel::WarmStartKept kept(model.elastic());  // the steps' results stay the same
    const Points& control = simulator_.positions();
    model.nodesFromControl(control, nodes_);
    const FormState state{control, nodes_};
    gradient_.setZero(control.rows(), nodes_.rows());
    const Clock::time_point start = Clock::now();
    elastic_.prepareAndAddGradient(state, gradient_);
    return millisecondsSince(start);
  }

 private:
  Simulator& simulator_;
  ElasticForm elastic_;
  Points nodes_;
  FormGradient gradient_;
};

uint32_t fixedCount(const Simulator& simulator) {
  const std::vector<uint8_t>& mask = simulator.fixedMask();
  return static_cast<uint32_t>(std::count(mask.begin(), mask.end(), uint8_t{1}));
}

struct BenchRun {
  int steps = 0;
  int paintEvery = 0;
  int paintFrom = 0;
  int pinEvery = 0;
  bool paintDensity = false;
  bool freshFactor = false;
  bool asWindow = false;  // worker factors taken when ready, never waited for
  bool trace = false;
  std::string levels;
  double setupMs = 0;
};

// The settings and setup lines, the stepping, and the figures; the exit code.
int benchAndPrint(Simulator& simulator, const BenchRun& run, std::optional<double> firstStepMs) {
  const FemModel& model = simulator.model();
  if (run.asWindow) {
    SimulationSettings window = simulator.settings();
    window.reproducible = false;
    simulator.setSettings(window);
  }
  const SimulationSettings& settings = simulator.settings();
  std::cout << "threads=" << workerCount() << " levels=" << run.levels
            << " integrator=" << integratorName(settings.integrator) << " dt=" << settings.timeStep
            << " steps=" << run.steps << " warmup=" << FemBenchOptions{}.warmupSteps
            << " paint_every=" << run.paintEvery
            << (run.paintFrom > 0 ? " paint_from=" + std::to_string(run.paintFrom) : "")
            << (run.paintDensity ? " paint_field=density" : "")
            << (run.pinEvery > 0 ? " pin_every=" + std::to_string(run.pinEvery) : "")
            << (run.freshFactor ? " fresh_factor=1" : "") << (run.asWindow ? " as_window=1" : "")
            << '\n'
            << "setup_ms=" << ms(run.setupMs) << " control_points=" << model.numControlPoints()
            << " nodes=" << model.numNodes() << " fixed=" << fixedCount(simulator) << '\n';
  std::cout.flush();

  FemBenchOptions options;
  options.steps = run.steps;
  options.paintEvery = run.paintEvery;
  options.paintFrom = run.paintFrom;
  options.paintDensity = run.paintDensity;
  options.pinEvery = run.pinEvery;
  options.freshFactor = run.freshFactor;
  options.trace = run.trace;
  options.firstStepMs = firstStepMs;
  const FemBenchFigures f = runFemBench(simulator, options, std::cerr);

  if (run.paintEvery > 0)
    std::cout << "dabs=" << f.dabs << " warmup_dabs=" << f.warmupDabs
              << " dab_radius=" << f.dabRadius << " painted_samples=" << f.paintedSamples << '\n';
  if (run.pinEvery > 0)
    std::cout << "pin_edits=" << f.pinEdits << " warmup_pin_edits=" << f.warmupPinEdits
              << " pinned_points=" << f.pinnedPoints << '\n';
  std::cout << app::allocatorLine() << '\n';
  const ElementCounts counts = model.mesh().counts();
  char mean[32], passes[32];
  std::snprintf(mean, sizeof mean, "%.1f", f.meanCgIterations);
  std::snprintf(passes, sizeof passes, "%.2f", f.stepPasses);
  std::cout << "fem_step_ms=" << ms(f.medianStepMs) << " elements=" << counts.total()
            << " tricubic=" << counts.tricubic << " trilinear=" << counts.trilinear
            << " pyramid=" << counts.pyramid << " cg_iterations=" << mean
            << " elastic_pass_ms=" << ms(f.elasticPassMs) << " step_passes=" << passes
            << " first_step_ms=" << ms(f.firstStepMs) << " step_p99_ms=" << ms(f.p99StepMs)
            << " step_max_ms=" << ms(f.maxStepMs) << '\n';
  return f.failed ? 1 : kExitSuccess;
}

// A control mesh: the FEM options' material and boxes, the lowest layer fixed without --fix,
// gravity.
int benchControlMesh(const CliArgs& args, const std::string& control, const BenchRun& given) {
  if (!args.has("levels") && !args.has("trilinear"))
    throw UsageError("--levels is required (or --trilinear)");
  if (args.has("cage")) throw UsageError("--cage is for surfaces caged as a scene");
  const FemCommandOptions options = parseFemOptions(args);
  const SimulationSettings settings = parseIntegratorAndStep(args, false);

  const std::optional<LoadedMesh> loaded = loadValidControlMesh(control);
  if (!loaded) return kExitBadInput;
  const CellComplex& mesh = loaded->mesh;
  // buildFemModel below refuses a level that would not fit before it allocates.
  std::cout << "file=" << control << " control_cells=" << mesh.numCells()
            << " control_vertices=" << mesh.numVertices() << '\n';
  std::cout.flush();

  BenchRun run = given;
  const Clock::time_point setupStart = Clock::now();
  std::optional<FemModel> model = buildFemModel(mesh, options.setup, control);
  if (!model) return kExitBadInput;
  run.setupMs = millisecondsSince(setupStart);
  run.levels =
      options.setup.trilinear ? std::string("trilinear") : std::to_string(options.setup.level);

  Simulator simulator(*model);
  if (const std::string problem = simulator.setSettings(settings); !problem.empty())
    throw UsageError(problem);
  applyConstraintsAndForces(simulator, options);
  if (options.fixed.empty()) fixLowestLayer(simulator);
  simulator.addLoad(std::make_unique<GravityForm>(*model, Eigen::Vector3d(0.0, -9.81, 0.0)));
  return benchAndPrint(simulator, run, std::nullopt);
}

// A surface, a project or the default scene, built as simulate builds it, with the scene's own
// pins, loads and settings. Its build takes the first step, which is first_step_ms.
int benchScene(const CliArgs& args, const std::string& file, const BenchRun& given) {
  const CliScene scene = cliSceneFor(args, file, "bench fem");
  BenchRun run = given;
  run.levels = std::to_string(scene.settings.level);
  const Clock::time_point setupStart = Clock::now();
  const std::optional<SceneBuildPhase1> phase1 =
      buildSceneGeometry(scene.source, scene.settings, 1);
  StageTimes times;
  std::unique_ptr<ScenePhysics> physics =
      phase1 ? ScenePhysics::build(phase1->geometry, phase1->solid, scene.settings, nullptr, &times)
             : nullptr;
  if (!physics) return printError(file + ": the scene build was cancelled");
  const double buildMs = millisecondsSince(setupStart);
  double firstStepMs = 0;
  for (const auto& [stage, stageMs] : times)
    if (stage == "first step") firstStepMs = stageMs;
  run.setupMs = buildMs - firstStepMs;

  const CellComplex& control = physics->model().control();
  std::cout << "file=" << file << " control_cells=" << control.numCells()
            << " control_vertices=" << control.numVertices() << '\n';
  std::cerr << "bench fem: " << phase1->geometry->description << '\n';
  return benchAndPrint(physics->simulator(), run, firstStepMs);
}

}  // namespace

uint32_t fixLowestLayer(Simulator& simulator) {
  const Points& rest = simulator.model().restControl();
  const double low = rest.col(1).minCoeff();
  const double extent = (rest.colwise().maxCoeff() - rest.colwise().minCoeff()).maxCoeff();
  const double tolerance = 1e-9 * std::max(extent, 1.0);
  const double inf = std::numeric_limits<double>::infinity();
  return simulator.fixInBox(Eigen::AlignedBox3d(Eigen::Vector3d(-inf, low - tolerance, -inf),
                                                Eigen::Vector3d(inf, low + tolerance, inf)));
}

double controlCellSize(const FemModel& model) {
  const FemMesh& mesh = model.mesh();
  const double volume = std::accumulate(mesh.gaussVolume.begin(), mesh.gaussVolume.end(), 0.0);
  return std::cbrt(volume / std::max<uint32_t>(model.control().numCells(), 1));
}

FemBenchFigures runFemBench(Simulator& simulator, const FemBenchOptions& options,
                            std::ostream& err) {
  FemBenchFigures figures;
  auto step = [&] {
    const StepReport report = simulator.step();
    if (!report.ok || !report.message.empty()) {
      if (figures.failures == 0) err << "bench fem: " << report.message << '\n';
      ++figures.failures;
    }
    return report;
  };
  std::optional<DabPainter> painter;
  if (options.paintEvery > 0) {
    painter.emplace(simulator, options.paintDensity);
    figures.dabRadius = painter->radius();
  }
  std::optional<PinToggler> pins;
  if (options.pinEvery > 0) {
    pins.emplace(simulator);
    figures.pinnedPoints = pins->points();
  }
  // Before step `stepIndex` (warm-up or measured), the dab or pin edit due, outside the timing:
  // the step pays for what the edit changed.
  auto editBefore = [&](int stepIndex, bool measured) {
    bool edited = false;
    const bool painting = options.paintFrom == 0 || (measured && stepIndex >= options.paintFrom);
    if (painter && painting && stepIndex % options.paintEvery == 0) {
      painter->paintNext();
      ++(measured ? figures.dabs : figures.warmupDabs);
      edited = true;
    }
    if (pins && stepIndex % options.pinEvery == 0) {
      pins->toggle();
      ++(measured ? figures.pinEdits : figures.warmupPinEdits);
      edited = true;
    }
    if (edited && options.freshFactor) simulator.refactorPreconditioner();
  };

  if (options.firstStepMs) {
    figures.firstStepMs = *options.firstStepMs;
  } else {
    const Clock::time_point start = Clock::now();
    step();
    figures.firstStepMs = millisecondsSince(start);
  }
  for (int i = 0; i < options.warmupSteps; ++i) {
    editBefore(i, false);
    step();
  }
  // One elastic pass is timed before every measured step, so that the two medians share the
  // machine's state (its speed drifts by tens of percent within a minute on a shared VM).
  ElasticPassTimer passTimer(simulator);
  passTimer.timeOnePass();  // untimed: the first call allocates
  std::vector<double> samples, passSamples;
  long long iterations = 0;
  for (int i = 0; i < options.steps; ++i) {
    editBefore(i, true);
    passSamples.push_back(passTimer.timeOnePass());
    const Clock::time_point start = Clock::now();
    const StepReport report = step();
    samples.push_back(millisecondsSince(start));
    if (options.trace)
      err << "step=" << i << " ms=" << ms(samples.back()) << " cg_iterations=" << report.iterations
          << " elastic_pass_ms=" << ms(passSamples.back())
          << " barrier_elements=" << simulator.model().elastic().barrierElements()
          << " factorizations=" << simulator.preconditionerStats().factorizations
          << " extensions=" << simulator.preconditionerStats().extensions << '\n';
    iterations += report.iterations;
    figures.failed = figures.failed || !report.ok;
  }
  const int stepsTaken = options.warmupSteps + options.steps + (options.firstStepMs ? 0 : 1);
  if (figures.failures > 1)
    err << "bench fem: " << figures.failures << " of " << stepsTaken
        << " steps needed sub-steps or failed\n";

  if (!samples.empty()) {
    figures.medianStepMs = median(samples);
    figures.p99StepMs = percentile(samples, 99.0);
    figures.maxStepMs = *std::max_element(samples.begin(), samples.end());
    figures.meanCgIterations = static_cast<double>(iterations) / double(samples.size());
  }
  if (!passSamples.empty()) figures.elasticPassMs = median(passSamples);
  figures.stepPasses = figures.elasticPassMs > 0 ? figures.medianStepMs / figures.elasticPassMs
                                                 : std::numeric_limits<double>::infinity();
  if (painter) figures.paintedSamples = painter->samplesPainted();
  return figures;
}

int benchFemCommand(const CliArgs& args, std::string& file) {
  if (args.positional().size() != 2)
    throw UsageError("bench fem needs exactly one CONTROL file or SCENE (see --help)");
  if (args.has("repeat"))
    throw UsageError("--repeat applies to bench subdivide only (use --steps)");
  BenchRun run;
  run.steps = args.intValue("steps", 100, 1, 1'000'000);
  run.paintEvery = args.intValue("paint-every", 0, 1, 1'000'000);
  run.paintFrom = args.intValue("paint-from", 0, 0, 1'000'000);
  if (args.has("paint-from") && run.paintEvery == 0)
    throw UsageError("--paint-from says when the dabs start: it needs --paint-every");
  run.pinEvery = args.intValue("pin-every", 0, 1, 1'000'000);
  run.freshFactor = args.has("fresh-factor");
  const std::string field = args.value("paint-field").value_or("youngs");
  if (field != "youngs" && field != "density")
    throw UsageError("--paint-field is youngs or density, not '" + field + "'");
  run.paintDensity = field == "density";
  if (args.has("paint-field") && run.paintEvery == 0)
    throw UsageError("--paint-field chooses what the dabs paint: it needs --paint-every");
  run.asWindow = args.has("as-window");
  run.trace = args.has("trace");
  if (run.freshFactor && run.paintEvery == 0 && run.pinEvery == 0)
    throw UsageError(
        "--fresh-factor refactors after each dab or pin edit: it needs --paint-every or "
        "--pin-every");
  file = args.positional()[1];
  if (lowerExtension(file) == ".json") return benchControlMesh(args, file, run);
  return benchScene(args, file, run);
}

}  // namespace sculpt::cli
