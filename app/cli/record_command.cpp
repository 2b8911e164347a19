// sculpt-cli record SCENE [--script S.json] [--seconds T] [--fps F] [--levels K] [--cage N]
// [--integrator I] [--dt S] [--key-tolerance R] --out OUT [--out OUT2 ...]: simulates a scene
// as the window does, records a take at a fixed simulated frame rate and writes it to every OUT.

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "anim/recorder.h"
#include "anim/take_export.h"
#include "anim/take_surface.h"
#include "cli/cli_args.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/fem_options.h"
#include "cli/record_rendering.h"
#include "cli/scene_options.h"
#include "io/file_error.h"
#include "scene/scene_physics.h"

namespace sculpt::cli {

const char* const kRecordUsage =
    "  record SCENE [--script SESSION.json] [--seconds T] [--fps F] [--levels K] [--cage N]\n"
    "         [--integrator paper|implicit] [--dt S] [--key-tolerance R]\n"
    "         [--no-ui] [--supersample 1|2|4] [--transparent] [--size WxH]\n"
    "         --out OUT [--out OUT2 ...]\n"
    "      Simulates SCENE (what simulate accepts: a control mesh .json, a .sculpt project, an\n"
    "      OBJ/glTF surface in a cage; 'default': the window's default scene, the refined\n"
    "      bunny) as the window runs it, replaying the script, and records\n"
    "      T simulated seconds (default: the script's length) at F frames per simulated second\n"
    "      (default 30; 0 < F <= 1000; at most 100000 frames). Frame 0 is the state after the\n"
    "      first step; frame k the step nearest to k/F s. The extension of each OUT picks the\n"
    "      format: .glb (morph targets at key frames, cross-faded; every frame within R times\n"
    "      the rest bounding-box diagonal, default 1e-3), .pc2 and .mdd (point caches for\n"
    "      Blender's Mesh Cache), name_####.obj (the surface per frame), name_####.vtk (the\n"
    "      level-K solid per frame, with name.pvd and name.vtk.series), name_####.vtu (XML,\n"
    "      with name.pvd), name_####.png and .mp4 (rendered by the window program 'sculpt'\n"
    "      beside sculpt-cli, under xvfb-run when there is no display; .mp4 needs ffmpeg).\n"
    "      Several --out record one simulation into several files. Progress on stderr; last\n"
    "      line: frames=<n> seconds=<s> vertices=<n> keys=<n> bytes=<total>.\n";

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

// Progress lines about once per second.
ProgressReporter progressLines(const std::string& what) {
  auto last = std::make_shared<Clock::time_point>(Clock::now());
  return ProgressReporter([what, last](double fraction, std::string_view) {
    if (Clock::now() - *last >= std::chrono::seconds(1)) {
      *last = Clock::now();
      char line[64];
      std::snprintf(line, sizeof line, " %3.0f%%", 100.0 * fraction);
      std::cerr << "record: " << what << line << '\n';
    }
    return true;
  });
}

struct Output {
  std::filesystem::path path;
  ExportFormat format;
};

int recordCommand(const CliArgs& args, std::string& file) {
  if (args.has("help")) {
    std::cout << "usage:\n" << kRecordUsage;
    return kExitSuccess;
  }
  if (args.positional().size() != 1)
    throw UsageError("record needs exactly one SCENE (see --help)");
  file = args.positional()[0];
  std::vector<Output> outputs;
  for (const std::string& out : args.values("out")) {
    const ExportTarget target = exportTargetFor(out);
    if (!target.format) throw UsageError(target.problem);
    outputs.push_back({out, *target.format});
  }
  if (outputs.empty()) throw UsageError("--out is required (one or more)");
  const double fps = args.has("fps") ? parseNumber(args.requiredValue("fps"), "--fps") : 30.0;
  if (const std::string problem = frameRateProblem(fps); !problem.empty())
    throw UsageError(problem);
  const double keyTolerance =
      args.has("key-tolerance")
          ? parseNumber(args.requiredValue("key-tolerance"), "--key-tolerance")
          : 1e-3;
  if (!(keyTolerance > 0.0 && keyTolerance < 1.0))
    throw UsageError("--key-tolerance must be more than 0 and less than 1 (a fraction of the "
                     "bounding-box diagonal)");

  CliScene scene = cliSceneFor(args, file, "record");
  if (!args.has("seconds") && !scene.script)
    throw UsageError("--seconds is required (or --script, whose length is the default)");
  const double recorded = args.has("seconds")
                              ? parseNumber(args.requiredValue("seconds"), "--seconds")
                              : scene.script->duration();
  if (!(recorded >= 0.0) || !std::isfinite(recorded))
    throw UsageError("--seconds must be a finite number >= 0");
  const double wantedFrames = std::floor(recorded * fps + 0.5) + 1.0;
  if (wantedFrames > kMaxTakeFrames)
    throw UsageError(std::to_string(static_cast<long long>(wantedFrames)) + " frames (" +
                     std::to_string(recorded) + " s at " + std::to_string(fps) +
                     " fps) are more than a take holds (" + std::to_string(kMaxTakeFrames) + ")");
  const uint32_t frames = static_cast<uint32_t>(wantedFrames);
  const RenderOptions render = parseRenderOptions(args);

  // The scene, built and run as the window runs it (core/scene).
  const Clock::time_point start = Clock::now();
  std::optional<SceneBuildPhase1> phase1 = buildSceneGeometry(scene.source, scene.settings, 1);
  StageTimes times;
  std::unique_ptr<ScenePhysics> physics =
      ScenePhysics::build(phase1->geometry, phase1->solid, scene.settings, nullptr, &times);
  const SceneGeometry& geometry = physics->geometry();
  std::cerr << "record: " << geometry.description << ", " << geometry.restPositions.rows()
            << " surface vertices, " << frames << " frames at " << fps << " fps\n";
  if (scene.script) physics->playScript(*scene.script);  // after the build's step, as the window

  Recorder recorder(fps);
  recorder.start();
  Clock::time_point lastProgress = Clock::now();
  uint64_t steps = 0;
  while (recorder.frameCount() < frames) {
    const StepReport report = physics->step();
    ++steps;
    if (!report.ok)
      std::cerr << "record: step " << steps << " failed"
                << (report.message.empty() ? std::string() : ": " + report.message)
                << "; the take keeps its state\n";
    StepState state;
    state.sceneId = geometry.sceneId;
    state.step = steps;
    state.simulatedTime = physics->simulatedTime();
    state.control = &physics->simulator().positions();
    state.report = &report;
    state.physics = physics.get();
    recorder.observe(state);
    if (Clock::now() - lastProgress >= std::chrono::seconds(1)) {
      lastProgress = Clock::now();
      std::cerr << "record: frame " << recorder.frameCount() << "/" << frames << " (t = "
                << state.simulatedTime << " s, " << seconds(start) << " s)\n";
    }
  }
  recorder.stop();
  const std::shared_ptr<const Take> take = recorder.take();
  std::cerr << "record: " << take->frameCount() << " frames in " << seconds(start) << " s ("
            << take->memoryBytes() / 1024 << " KiB of control points)\n";

  // Every output. One that fails does not stop the others; the exit code says so.
  TakeSurface surface(take);
  TakeExportOptions options;
  options.keyTolerance = keyTolerance;
  uint64_t bytes = 0;
  uint32_t keys = 0;
  int failures = 0;
  for (const Output& out : outputs) {
    const Clock::time_point begin = Clock::now();
    try {
      ExportResult result;
      if (isRenderedFormat(out.format)) {
        result = renderRecording(file, args, recorded, fps, out.path, out.format, render, frames);
      } else {
        ProgressReporter progress = progressLines(out.path.string());
        result = exportAnimation(surface, out.path, out.format, options, &progress);
      }
      bytes += result.bytes;
      keys += result.keys;
      std::cerr << "record: wrote " << out.path.string() << " (" << exportFormatName(out.format)
                << ", " << result.files.size() << " files, " << result.bytes << " bytes"
                << (result.keys ? ", " + std::to_string(result.keys) + " keys" : std::string())
                << ", " << seconds(begin) << " s)\n";
    } catch (const std::exception& e) {
      std::cerr << "error: " << e.what() << '\n';
      ++failures;
    }
  }
  std::printf("frames=%u seconds=%.9g vertices=%u keys=%u bytes=%llu\n", take->frameCount(),
              take->duration(), surface.maxVertices(), keys,
              static_cast<unsigned long long>(bytes));
  return failures ? kExitBadInput : kExitSuccess;
}

}  // namespace

int runRecordCommand(const std::vector<std::string>& args) {
  std::string file;
  return runGuarded(file, [&] {
    const std::vector<OptionSpec> specs = {
        {"script", true},  {"seconds", true}, {"fps", true},        {"levels", true},
        {"level", true},   {"cage", true},    {"integrator", true}, {"dt", true},
        {"key-tolerance", true}, {"out", true}, {"no-ui", false}, {"supersample", true},
        {"transparent", false}, {"size", true}, {"help", false}};
    return recordCommand(CliArgs::parse(args, specs), file);
  });
}

}  // namespace sculpt::cli
