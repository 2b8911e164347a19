// sculpt-cli simulate CONTROL [--levels K | --trilinear] [--integrator paper|implicit] --dt S
// [--steps N] [--gravity] [--fix BOX]... [--force BOX FX,FY,FZ]... [--script SESSION.json]
// --out FINAL.vtk: time integration from rest under box forces, gravity and a session script.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "cli/cli_args.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/fem_options.h"
#include "cli/scene_options.h"
#include "io/control_mesh_json.h"
#include "sim/standard_forms.h"
#include "tools/script_topology.h"
#include "tools/session_script.h"
#include "util/short_number.h"
#include "project/project_file.h"
#include "scene/control_export.h"
#include "scene/scene_file.h"
#include "scene/scene_physics.h"

namespace sculpt::cli {

const char* const kSimulateUsage =
    "  simulate CONTROL.json [FEM options] [--integrator paper|implicit] [--model M] --dt S\n"
    "           --steps N [--gravity] [--script SESSION.json] --out FINAL.vtk\n"
    "  simulate SCENE [--levels K] [--cage N] [--integrator paper|implicit] [--model M]\n"
    "           [--dt S] [--steps N] [--script SESSION.json] --out FINAL.vtk\n"
    "      Integrates N steps of S seconds from rest (0 < S <= 10, 1 <= N <= 10000000) with\n"
    "      the paper's central differences or backward Euler (implicit, the default).\n"
    "      --gravity adds g = (0, -9.81, 0) m/s^2: the y axis points up. A step that fails is\n"
    "      retried with halved sub-steps; stderr gets a progress line about once per second\n"
    "      ('[time] step i/N t=.. kinetic=.. elastic=..'), the first message of each kind of\n"
    "      step report and a count per kind at the end. The run stops at the first step that\n"
    "      fails even with sub-steps (exit 1) and keeps the state before it. FINAL.vtk is the\n"
    "      deformed control mesh with the POINT_DATA vector 'displacement'. Last line:\n"
    "      steps=<completed> time=<s> max_displacement=<m> kinetic_energy=<J>\n"
    "      elastic_energy=<J> substeps=<total> cg_iterations=<mean per step> model=<M>\n"
    "      min_jacobian=<smallest det F of a Gauss point> inverted_elements=<n>.\n"
    "      --model barrier (default: co-rotated elasticity with an inversion barrier) or\n"
    "      corotated (the paper's, without it).\n"
    "      --script replays a session script (docs/file-formats.md) while stepping: grabs,\n"
    "      inflation, paint and pins at their times; each event's start and end go to\n"
    "      stderr. With --script, --steps defaults to the script's length. A malformed\n"
    "      script is one error line naming the event and field (exit 2). Topology events\n"
    "      (t = 0) edit CONTROL in file order before the model is built, so the run starts\n"
      "      from the edited rest shape; one that cannot be applied is an error (exit 2).\n"
    "      SCENE is a surface (OBJ, glTF) caged as the window cages it, or a .sculpt project\n"
    "      (its cage or control mesh, pins, painted materials and saved settings): the scene\n"
    "      the window runs, with its defaults (a surface: the top layer pinned, gravity, a\n"
    "      1/60 s step, level 1, a 6-cell cage), which the options override. N counts every\n"
    "      step, the build's first one included; the script starts after it, as in the\n"
    "      window, so `sculpt --headless --scene SCENE --script S --frames N --out F.vtk`\n"
    "      writes the same control points.\n";

namespace {

constexpr int kMaxSteps = 10'000'000;
constexpr size_t kMaxMessageKinds = 10;
const Eigen::Vector3d kGravity(0.0, -9.81, 0.0);

using Clock = std::chrono::steady_clock;

// The message with every number replaced by '#': reports that differ only in their figures
// (energies, sub-step counts) are one kind.
std::string messageKind(const std::string& message) {
  std::string kind;
  for (size_t i = 0; i < message.size();) {
    const bool digit = message[i] >= '0' && message[i] <= '9';
    if (!digit) {
      kind += message[i++];
      continue;
    }
    while (i < message.size()) {
      const char c = message[i];
      const bool exponent = (c == 'e' || c == 'E') && i + 1 < message.size() &&
                            ((message[i + 1] >= '0' && message[i + 1] <= '9') ||
                             message[i + 1] == '-' || message[i + 1] == '+');
      if ((c >= '0' && c <= '9') || c == '.') {
        ++i;
      } else if (exponent) {
        i += 2;
      } else {
        break;
      }
    }
    kind += '#';
  }
  return kind;
}

struct MessageKind {
  std::string kind;
  int firstStep = 0;
  long count = 0;
};

// Prints the first message of each kind as it comes and the counts at the end.
class StepMessages {
 public:
  void add(int step, const std::string& message) {
    const std::string kind = messageKind(message);
    for (MessageKind& k : kinds_) {
      if (k.kind == kind) {
        ++k.count;
        return;
      }
    }
    if (kinds_.size() == kMaxMessageKinds) {
      if (suppressed_++ == 0)
        std::cerr << "simulate: more kinds of step messages; further ones are only counted\n";
      return;
    }
    kinds_.push_back({kind, step, 1});
    std::cerr << "simulate: step " << step << ": " << message << '\n';
  }
  // A count for each kind that came more than once.
  void printSummary(int stepsRun) const {
    for (const MessageKind& k : kinds_)
      if (k.count > 1)
        std::cerr << "simulate: " << k.count << " of " << stepsRun
                  << " steps reported a message like step " << k.firstStep << "'s\n";
    if (suppressed_ > 0)
      std::cerr << "simulate: " << suppressed_ << " more steps reported other messages\n";
  }

 private:
  std::vector<MessageKind> kinds_;
  long suppressed_ = 0;
};

// The stepping shared by control meshes and scenes: progress about once per second, the first
// message of each kind, a stop at the first step that fails even with sub-steps.
struct StepTotals {
  int completed = 0;
  long long substeps = 0, iterations = 0;
  bool failed = false;
  int stepsRun() const { return completed + (failed ? 1 : 0); }
};

StepTotals runSteps(int first, int steps, const std::string& out, Simulator& simulator,
                    const std::function<StepReport()>& step,
                    const std::function<void()>& afterStep) {
  const Clock::time_point start = Clock::now();
  Clock::time_point lastProgress = start;
  StepMessages messages;
  StepTotals totals;
  for (int i = first; i <= steps; ++i) {
    const StepReport report = step();
    if (afterStep) afterStep();
    totals.iterations += report.iterations;
    if (report.ok) {
      ++totals.completed;
      totals.substeps += report.substeps;
    }
    if (!report.message.empty() || !report.ok)
      messages.add(i, report.message.empty() ? "step failed" : report.message);
    if (!report.ok) {
      totals.failed = true;
      std::cerr << "simulate: stopped at step " << i << " of " << steps << "; " << out
                << " holds the state before it\n";
      break;
    }
    const Clock::time_point now = Clock::now();
    if (now - lastProgress >= std::chrono::seconds(1) && i < steps) {
      lastProgress = now;
      char line[160];
      std::snprintf(line, sizeof line,
                    "[%7.2f s] step %d/%d t=%.6g s kinetic=%.4g J elastic=%.4g J",
                    std::chrono::duration<double>(now - start).count(), i, steps, simulator.time(),
                    simulator.kineticEnergy(), simulator.elasticEnergy());
      std::cerr << line << '\n';
    }
  }
  messages.printSummary(totals.stepsRun());
  return totals;
}

void printTotals(const StepTotals& totals, double time, double maxDisplacement,
                 Simulator& simulator) {
  Points nodes;
  simulator.model().nodesFromControl(simulator.positions(), nodes);
  const ElasticKernel::Jacobians jacobians = simulator.model().elastic().jacobians(nodes);
  std::printf(
      "steps=%d time=%.9g max_displacement=%.9g kinetic_energy=%.9g elastic_energy=%.9g "
      "substeps=%lld cg_iterations=%.1f model=%s min_jacobian=%.6g inverted_elements=%u\n",
      totals.completed, time, maxDisplacement, simulator.kineticEnergy(), simulator.elasticEnergy(),
      totals.substeps, static_cast<double>(totals.iterations) / std::max(1, totals.stepsRun()),
      elasticModelName(simulator.settings().elasticModel), jacobians.min,
      jacobians.invertedElements);
}

// "events[3] (inflate) ends at t=1e+09 s": the event that sets the script's length.
std::string lastEventText(const SessionScript& script) {
  const ScriptEvent* last = script.lastEvent();
  return "events[" + std::to_string(last->index) + "] (" + last->typeName() +
         ") ends at t=" + shortNumber(last->endTime()) + " s";
}

// --steps, or the script's length in steps (`extra` for a build's own first step). A script
// longer than kMaxSteps is refused rather than cut short hours later; a --steps that ends
// before the script does gets a note, as its last events will not be reached.
int stepsFor(const CliArgs& args, const std::optional<SessionScript>& script, double timeStep,
             int extra) {
  if (!args.has("steps") && !script) throw UsageError("--steps is required (or --script)");
  const std::string scriptName = args.value("script").value_or("the script");
  if (args.has("steps")) {
    const int steps = args.intValue("steps", 0, 1, kMaxSteps);
    if (script && script->lastEvent() &&
        double(steps - extra) * timeStep < script->duration() * (1 - 1e-12))
      std::cerr << "simulate: note: --steps " << steps
                << " ends at t=" << shortNumber(double(steps - extra) * timeStep) << " s, before "
                << scriptName << "'s " << lastEventText(*script) << '\n';
    return steps;
  }
  const double needed = std::ceil(script->duration() / timeStep - 1e-9) + extra;
  if (needed > double(kMaxSteps))
    throw UsageError(scriptName + ": " + lastEventText(*script) + ", which takes " +
                     shortNumber(needed) + " steps of " + shortNumber(timeStep) + " s (at most " +
                     std::to_string(kMaxSteps) +
                     "); use a larger --dt, or --steps to run part of it");
  return static_cast<int>(std::max(needed, 1.0));
}

// A surface or a project, built and run by the scene pipeline the window uses (core/scene).
int simulateScene(const CliArgs& args, const std::string& file, const std::string& out) {
  CliScene scene = cliSceneFor(args, file, "simulate");
  const SceneSettings& settings = scene.settings;
  std::optional<SessionScript>& script = scene.script;
  const int steps = stepsFor(args, script, settings.timeStep, 1);

  std::optional<SceneBuildPhase1> phase1 = buildSceneGeometry(scene.source, settings, 1);
  StageTimes times;
  std::unique_ptr<ScenePhysics> physics =
      ScenePhysics::build(phase1->geometry, phase1->solid, settings, nullptr, &times);
  std::cerr << "simulate: " << phase1->geometry->description << ", "
            << physics->model().numControlPoints() << " control points\n";
  if (script)
    physics->playScript(*script);  // from the step after the build's first one, as the window
  Simulator& simulator = physics->simulator();
  StepTotals totals = runSteps(2, steps, out, simulator, [&] { return physics->step(); }, [&] {
    for (const std::string& line : physics->takeScriptLog())
      std::cerr << "simulate: script: " << line << '\n';
  });
  ++totals.completed;  // the build's first step
  sculpt::writeDeformedControlVtk(physics->model().control(), simulator.positions(), out);
  printTotals(totals, physics->simulatedTime(),
              maxNodeDisplacement(physics->model(), simulator.positions()), simulator);
  return totals.failed ? 1 : kExitSuccess;
}

int simulateCommand(const CliArgs& args, std::string& file) {
  if (args.has("help")) {
    std::cout << "usage:\n" << kSimulateUsage << kFemOptionsUsage;
    return kExitSuccess;
  }
  if (args.positional().size() != 1)
    throw UsageError("simulate needs exactly one CONTROL file (see --help)");
  const std::string out = args.requiredValue("out");
  if (lowerExtension(out) != ".vtk")
    throw UsageError("--out " + out + ": unknown extension (expected .vtk)");
  file = args.positional()[0];
  if (lowerExtension(file) != ".json") return simulateScene(args, file, out);
  if (args.has("cage")) throw UsageError("--cage is for surfaces caged as a scene");
  const FemCommandOptions options = parseFemOptions(args);
  SimulationSettings settings = parseIntegratorAndStep(args, true);
  // The script is read before the model is built, so that a bad one fails fast.
  std::optional<SessionScript> script;
  if (args.has("script")) script = loadSessionScript(args.requiredValue("script"));
  const int steps = stepsFor(args, script, settings.timeStep, 0);

  const std::optional<LoadedMesh> loaded = loadValidControlMesh(file);
  if (!loaded) return kExitBadInput;
  CellComplex control = loaded->mesh;
  if (script) {
    const size_t events = script->events.size();
    try {
      control = applyTopologyEvents(control, *script,
                                    options.setup.trilinear ? 0 : options.setup.level);
    } catch (const std::invalid_argument& e) {
      return printError(args.requiredValue("script") + ": " + e.what());
    }
    if (script->events.size() != events)
      std::cerr << "simulate: script: " << events - script->events.size()
                << " topology events applied: " << control.numCells() << " cells, "
                << control.numVertices() << " control points\n";
  }
  std::optional<FemModel> model = buildFemModel(control, options.setup, file);
  if (!model) return kExitBadInput;

  Simulator simulator(*model);
  if (const std::string problem = simulator.setSettings(settings); !problem.empty())
    throw UsageError(problem);
  applyConstraintsAndForces(simulator, options);
  if (args.has("gravity")) simulator.addLoad(std::make_unique<GravityForm>(*model, kGravity));
  std::optional<ScriptPlayer> player;
  if (script) player.emplace(simulator, std::move(*script));

  const StepTotals totals = runSteps(1, steps, out, simulator,
      [&] { return player ? player->step() : simulator.step(); },
      [&] {
        if (player)
          for (const std::string& line : player->takeLog())
            std::cerr << "simulate: script: " << line << '\n';
      });
  writeDeformedControlVtk(*model, simulator.positions(), out);
  printTotals(totals, simulator.time(), maxNodeDisplacement(*model, simulator.positions()),
              simulator);
  return totals.failed ? 1 : kExitSuccess;
}

}  // namespace

int runSimulateCommand(const std::vector<std::string>& args) {
  std::string file;
  return runGuarded(file, [&] {
    std::vector<OptionSpec> specs = kFemOptions;
    specs.insert(specs.end(), {{"integrator", true},
                               {"model", true},
                               {"dt", true},
                               {"steps", true},
                               {"gravity", false},
                               {"out", true},
                               {"script", true},
                               {"cage", true},
                               {"help", false}});
    return simulateCommand(CliArgs::parse(args, specs), file);
  });
}

}  // namespace sculpt::cli
