// sculpt-cli haptics SCENE --device mock --device-script D.json [--script S.json] --out F.csv:
// the 1 kHz servo with the mock PHANTOM-class device against the real simulation on its thread.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "cli/cli_args.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/fem_options.h"
#include "cli/scene_options.h"
#include "haptics/mock/device_script.h"
#include "haptics/mock/mock_phantom.h"
#include "haptics/session/haptic_session.h"
#include "io/atomic_file.h"
#include "scene/scene_physics.h"
#include "scene/simulation_loop.h"

namespace sculpt::cli {

const char* const kHapticsUsage =
    "  haptics SCENE --device mock --device-script DEVICE.json [--script SESSION.json]\n"
    "          [--tool pull|probe|paint|inflate] [--seconds T] [--force-factor F]\n"
    "          [--levels K] [--cage N] [--integrator paper|implicit] [--dt S] --out FORCES.csv\n"
    "      Runs the haptic servo at 1 kHz on its own thread with the mock PHANTOM-class device\n"
    "      following DEVICE.json (docs/file-formats.md \"Device scripts\") against the scene's\n"
    "      simulation running in real time on its thread, as the window runs a stylus. The\n"
    "      tool is the script's \"tool\" (pull unless it says), or --tool. SESSION.json is\n"
    "      played from the start (paint or pin first). T defaults to the device script's\n"
    "      length plus 0.5 s. FORCES.csv: one row per servo tick (time, device position,\n"
    "      commanded force, force before the safety limits, the coupling's force on the solid,\n"
    "      probe age). Last line: servo_hz_mean=.. period_p99_ms=.. max_force_n=..\n"
    "      force_limit_n=.. clamped_ticks=.. sim_steps_per_s=.. contact_force_mean_n=..\n";

namespace {


haptics::NamedHapticTool toolNamed(const std::string& name) {
  if (const std::optional<haptics::NamedHapticTool> named = haptics::hapticToolNamed(name))
    return *named;
  throw UsageError("--tool " + name + ": expected pull, probe, paint or inflate");
}

double numberIn(const CliArgs& args, const char* option, double lo, double hi) {
  const double value = parseNumber(args.requiredValue(option), std::string("--") + option);
  if (!(value >= lo && value <= hi))
  {
    char range[96];
    std::snprintf(range, sizeof range, ": expected a number from %g to %g", lo, hi);
    throw UsageError(std::string("--") + option + " " + args.requiredValue(option) + range);
  }
  return value;
}

void writeForces(const std::string& path, const std::vector<haptics::ServoRecord>& records) {
  std::string text =
      "time_s,device_x_m,device_y_m,device_z_m,force_x_n,force_y_n,force_z_n,"
      "unclamped_x_n,unclamped_y_n,unclamped_z_n,unclamped_n,solid_x_n,solid_y_n,solid_z_n,"
      "probe_age_ms\n";
  text.reserve(text.size() + records.size() * 200);
  char line[512];
  for (const haptics::ServoRecord& r : records) {
    std::snprintf(line, sizeof line,
                  "%.6f,%.7g,%.7g,%.7g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.3f\n",
                  r.time, r.devicePosition.x(), r.devicePosition.y(), r.devicePosition.z(),
                  r.commanded.x(), r.commanded.y(), r.commanded.z(), r.desired.x(), r.desired.y(),
                  r.desired.z(), r.desired.norm(), r.onSolid.x(), r.onSolid.y(), r.onSolid.z(),
                  r.probeAge * 1e3);
    text += line;
  }
  writeFileAtomically(path, text);
}

int hapticsCommand(const CliArgs& args, std::string& file) {
  if (args.has("help")) {
    std::cout << "usage:\n" << kHapticsUsage;
    return kExitSuccess;
  }
  if (args.positional().size() != 1)
    throw UsageError("haptics needs exactly one SCENE (see --help)");
  if (args.requiredValue("device") != "mock")
    throw UsageError("--device " + args.requiredValue("device") +
                     ": only the mock device runs from the command line (a real stylus runs in "
                     "the window)");
  const std::string out = args.requiredValue("out");
  if (lowerExtension(out) != ".csv") throw UsageError("--out " + out + ": expected a .csv file");
  file = args.positional()[0];
  const std::string deviceScriptPath = args.requiredValue("device-script");
  const haptics::DeviceScript deviceScript = haptics::loadDeviceScript(deviceScriptPath);
  const auto [tool, paint] = toolNamed(
      args.value("tool").value_or(deviceScript.tool.empty() ? "pull" : deviceScript.tool));
  const double seconds = args.has("seconds") ? numberIn(args, "seconds", 0.01, 600)
                                             : deviceScript.duration() + 0.5;
  const double factor = args.has("force-factor") ? numberIn(args, "force-factor", 1e-6, 1e6) : 1.0;

  CliScene scene = cliSceneFor(args, file, "haptics");
  std::optional<SceneBuildPhase1> phase1 = buildSceneGeometry(scene.source, scene.settings, 1);
  StageTimes times;
  std::unique_ptr<ScenePhysics> physics =
      ScenePhysics::build(phase1->geometry, phase1->solid, scene.settings, nullptr, &times);
  std::cerr << "haptics: " << phase1->geometry->description << ", "
            << physics->model().numControlPoints() << " control points\n";
  if (scene.script) physics->playScript(*scene.script);
  SceneFrame first;
  physics->fillFrame(first);

  SimulationLoop loop(true);
  std::atomic<uint64_t> steps{0};
  loop.addStepObserver(
      [&steps](const StepState&) { steps.fetch_add(1, std::memory_order_relaxed); });
  loop.setProblemHandler(
      [](const std::string& problem) { std::cerr << "haptics: " << problem << '\n'; });
  loop.install(std::move(physics), std::move(first));

  haptics::MockPhantom device(deviceScript);
  haptics::HapticSessionSettings settings;
  settings.tool = tool;
  settings.paintWithProbe = paint;
  settings.forceFactor = factor;
  settings.recordTicks = static_cast<size_t>(seconds * 1000.0 * 1.5) + 1000;
  const haptics::HapticScene hapticScene = haptics::hapticSceneOf(phase1->geometry, scene.settings);
  if (paint) {  // ten times stiffer, a tenth of the scene's radius, no mirror
    settings.paint.brush.radius = 0.1 * hapticScene.radius;
    settings.paint.brush.target = scene.settings.material;
    settings.paint.brush.target.youngs *= 10.0;
    settings.paint.brush.mirror.x = false;
  }
  haptics::HapticSession session(loop, device, hapticScene, settings);
  std::cerr << "haptics: " << device.info().model << ", " << session.status().scale.describe()
            << "\n";
  const auto start = std::chrono::steady_clock::now();
  const uint64_t stepsAtStart = steps.load();
  session.start();
  for (int second = 1; second <= static_cast<int>(seconds); ++second) {
    std::this_thread::sleep_until(start + std::chrono::seconds(second));
    const haptics::HapticStatus status = session.status();
    std::fprintf(stderr, "haptics: t=%d s servo ticks=%llu force=%.3f N%s%s\n", second,
                 static_cast<unsigned long long>(status.servoTicks), status.force.norm(),
                 status.acting ? " (acting)" : "", status.tripped ? " TRIPPED" : "");
  }
  std::this_thread::sleep_until(start + std::chrono::duration<double>(seconds));
  session.stop();
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const uint64_t simulated = steps.load() - stepsAtStart;
  loop.setPlaying(false);

  const haptics::ServoStatistics stats = session.servo().statistics();
  const std::vector<haptics::ServoRecord>& records = session.servo().records();
  writeForces(out, records);
  double contactSum = 0;
  size_t contactTicks = 0;
  for (const haptics::ServoRecord& r : records)
    if (r.acting) contactSum += r.commanded.norm(), ++contactTicks;
  std::printf(
      "servo_hz_mean=%.1f period_p99_ms=%.3f max_force_n=%.4f force_limit_n=%.4g "
      "clamped_ticks=%llu sim_steps_per_s=%.1f contact_force_mean_n=%.4f\n",
      stats.meanHz, stats.periodP99Ms, stats.maxForce, device.info().maxForce,
      static_cast<unsigned long long>(stats.clampedTicks), static_cast<double>(simulated) / elapsed,
      contactTicks ? contactSum / static_cast<double>(contactTicks) : 0.0);
  return kExitSuccess;
}

}  // namespace

int runHapticsCommand(const std::vector<std::string>& args) {
  std::string file;
  return runGuarded(file, [&] {
    const std::vector<OptionSpec> specs = {{"device", true},     {"device-script", true},
                                           {"script", true},     {"tool", true},
                                           {"seconds", true},    {"force-factor", true},
                                           {"levels", true},     {"cage", true},
                                           {"integrator", true}, {"dt", true},
                                           {"out", true},        {"help", false}};
    return hapticsCommand(CliArgs::parse(args, specs), file);
  });
}

}  // namespace sculpt::cli
