#include "sculpt/options.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <stdexcept>

#include "anim/recorder.h"

namespace sculpt::app {

const char* const kUsage =
    "usage: sculpt [options] [FILE]\n"
    "  FILE, --scene FILE     project (.sculpt), control mesh (.json) or surface (.obj, .gltf,\n"
    "                         .glb) to open; default: the Stanford bunny in a hexahedral cage\n"
    "  --dt S                 simulated seconds per step (default: the scene's, 1/60)\n"
    "  --script FILE          replay a session script (docs/file-formats.md) on the scene\n"
    "  --level K              simulation level (1..3)\n"
    "  --cage N               cage cells across a surface (1..64, default 6)\n"
    "  --method M             phong | linear | vertex | attribute\n"
    "  --gradients G          fit | average: node gradients of phong and vertex (default fit)\n"
    "  --field F              none | youngs | density | displacement | strain | damping\n"
    "  --field-per-cell       show a cell field flat per level-K cell (default: smooth, from\n"
    "                         the node values)\n"
    "  --clip x|y|z           clipping plane through the middle of the solid\n"
    "  --wireframe --flat --show-cells --show-control --no-grid\n"
    "  --preset blender|stylus  mouse navigation preset (default blender)\n"
    "  --ui-scale S           1..3 (default: the monitor's content scale)\n"
    "  --show-help            open the keys-and-mouse overlay (F1) at start\n"
    "  --simulated-device     the mouse drives a mock haptic stylus (Touch), with its panel\n"
    "  --headless             render offscreen (needs an X display: use xvfb-run without one)\n"
    "  --screenshot OUT.png   headless: write the last frame there\n"
    "  --out FINAL.vtk        headless: write the final control mesh there (as sculpt-cli\n"
    "                         simulate --out does)\n"
    "  --frames N             headless: frames to simulate and draw (default 60)\n"
    "  --supersample 1|2|4    screenshot resolution factor (downsampled)\n"
    "  --transparent          screenshot with a transparent background\n"
    "  --no-ui                headless: the 3D view without panels\n"
    "  --bench N              headless: time N frames and print key=value figures\n"
    "  --record-seconds T     headless: record T simulated seconds of the scene (after --script\n"
    "                         starts) and write each --record-out\n"
    "  --record-out OUT       repeatable: a .glb, .pc2, .mdd, name_####.obj/.vtk/.vtu, or\n"
    "                         rendered as the screenshot is: name_####.png, name.mp4 (ffmpeg)\n"
    "  --fps F                frames per simulated second of a take (default 30; the window's\n"
    "                         Record too)\n"
    "  --size WxH             window size (default 1280x800)\n"
    "  --quit-after SECONDS   close the window that long after the first frame with the scene\n"
    "                         (smoke tests)\n";

namespace {

int intIn(const std::string& option, const std::string& text, int lo, int hi) {
  size_t used = 0;
  int value = 0;
  try {
    value = std::stoi(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || value < lo || value > hi)
    throw std::invalid_argument(option + " must be an integer in " + std::to_string(lo) + ".." +
                                std::to_string(hi) + " (got '" + text + "')");
  return value;
}

double positive(const std::string& option, const std::string& text) {
  size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !(value > 0.0 && value < 1e6))
    throw std::invalid_argument(option + " must be a positive number (got '" + text + "')");
  return value;
}

}  // namespace

Options parseOptions(int argc, char** argv, bool* helpShown) {
  Options options;
  bool framesGiven = false, sceneGiven = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "--scene" || arg == "--surface" || (!arg.empty() && arg[0] != '-')) {
      // A file named on its own is the scene (`sculpt work.sculpt`), as launchers pass it.
      const std::string file = arg[0] == '-' ? value() : arg;
      if (sceneGiven)
        throw std::invalid_argument("two scenes given ('" + options.scene + "' and '" + file +
                                    "'): the window opens one");
      options.scene = file;
      sceneGiven = true;
    } else if (arg == "--script") {
      options.script = value();
    } else if (arg == "--cage") {
      options.cage = intIn(arg, value(), 1, 64);
    } else if (arg == "--level") {
      options.level = intIn(arg, value(), 1, 3);
    } else if (arg == "--method") {
      const std::string name = value();
      const auto method = parseInterpolationMethod(name);
      if (!method)
        throw std::invalid_argument("--method must be phong, linear, vertex or attribute (got '" +
                                    name + "')");
      options.display.method = *method;
    } else if (arg == "--gradients") {
      const std::string name = value();
      const auto scheme = parseGradientScheme(name);
      if (!scheme)
        throw std::invalid_argument("--gradients must be fit or average (got '" + name + "')");
      options.display.gradients = *scheme;
    } else if (arg == "--field") {
      const std::string name = value();
      const auto field = parseField(name);
      if (!field)
        throw std::invalid_argument(
            "--field must be none, youngs, density, displacement, strain or damping (got '" +
            name + "')");
      options.display.field = *field;
    } else if (arg == "--field-per-cell") {
      options.display.smoothField = false;
    } else if (arg == "--clip") {
      const std::string axis = value();
      if (axis != "x" && axis != "y" && axis != "z")
        throw std::invalid_argument("--clip must be x, y or z (got '" + axis + "')");
      options.display.clip = true;
      options.display.clipAxis = axis[0] - 'x';
    } else if (arg == "--wireframe") {
      options.display.wireframe = true;
    } else if (arg == "--flat") {
      options.display.flatShading = true;
    } else if (arg == "--show-cells") {
      options.display.showCells = true;
    } else if (arg == "--show-control") {
      options.display.showControlMesh = true;
    } else if (arg == "--no-grid") {
      options.display.showGrid = options.display.showAxes = false;
    } else if (arg == "--preset") {
      const std::string name = value();
      if (name != "blender" && name != "stylus")
        throw std::invalid_argument("--preset must be blender or stylus (got '" + name + "')");
      options.stylusPreset = name == "stylus";
    } else if (arg == "--show-help") {
      options.showHelp = true;
    } else if (arg == "--ui-scale") {
      options.uiScale = static_cast<float>(positive(arg, value()));
      if (options.uiScale < 1.0f || options.uiScale > 3.0f)
        throw std::invalid_argument("--ui-scale must be in 1..3");
    } else if (arg == "--headless") {
      options.headless = true;
    } else if (arg == "--frames") {
      options.frames = intIn(arg, value(), 1, 100000);
      framesGiven = true;
    } else if (arg == "--screenshot") {
      options.screenshot = value();
    } else if (arg == "--out") {
      options.out = value();
    } else if (arg == "--supersample") {
      options.supersample = intIn(arg, value(), 1, 4);
      if (options.supersample == 3) throw std::invalid_argument("--supersample must be 1, 2 or 4");
    } else if (arg == "--transparent") {
      options.transparent = true;
    } else if (arg == "--simulated-device") {
      options.simulatedDevice = true;
    } else if (arg == "--no-ui") {
      options.noUi = true;
    } else if (arg == "--bench") {
      options.benchFrames = intIn(arg, value(), 1, 100000);
    } else if (arg == "--record-seconds") {
      options.recordSeconds = positive(arg, value());
    } else if (arg == "--record-out") {
      options.recordOut.push_back(value());
    } else if (arg == "--fps") {
      options.recordFps = positive(arg, value());
      if (const std::string problem = frameRateProblem(options.recordFps); !problem.empty())
        throw std::invalid_argument("--fps: " + problem);
    } else if (arg == "--size") {
      const std::string size = value();
      options.sizeGiven = true;
      char tail = 0;
      if (std::sscanf(size.c_str(), "%dx%d%c", &options.width, &options.height, &tail) != 2 ||
          options.width < 64 || options.height < 64 || options.width > 8192 ||
          options.height > 8192)
        throw std::invalid_argument("--size must be WxH between 64 and 8192 (got '" + size + "')");
    } else if (arg == "--dt") {
      options.timeStep = positive(arg, value());
      if (*options.timeStep > 10.0) throw std::invalid_argument("--dt must be at most 10 s");
    } else if (arg == "--quit-after") {
      options.quitAfter = positive(arg, value());
    } else if (arg == "--help" || arg == "-h") {
      std::cout << kUsage;
      if (helpShown) *helpShown = true;
      return options;
    } else {
      throw std::invalid_argument("unknown option '" + arg + "'");
    }
  }
  if (options.benchFrames > 0) options.headless = true;
  if ((options.recordSeconds > 0.0) != !options.recordOut.empty())
    throw std::invalid_argument("--record-seconds and --record-out go together");
  if (options.recordSeconds > 0.0 && !options.headless)
    throw std::invalid_argument("--record-seconds needs --headless");
  if (options.recordSeconds > 0.0 &&
      std::lround(options.recordSeconds * options.recordFps) + 1 > kMaxTakeFrames)
    throw std::invalid_argument("--record-seconds x --fps must stay under " +
                                std::to_string(kMaxTakeFrames) + " frames");
  if (options.headless && options.screenshot.empty() && options.out.empty() &&
      options.benchFrames == 0 && options.recordSeconds == 0.0)
    throw std::invalid_argument(
        "--headless needs --screenshot OUT.png, --out FINAL.vtk, --record-seconds T or --bench N");
  if (!options.headless &&
      (framesGiven || !options.screenshot.empty() || !options.out.empty() || options.noUi))
    throw std::invalid_argument("--frames, --screenshot, --out and --no-ui need --headless");
  return options;
}

}  // namespace sculpt::app
