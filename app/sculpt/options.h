#pragma once
// The window's command line:
//   sculpt [FILE | --scene FILE] [--level K] [--dt S] [--method M] [--field F] [--clip x|y|z]
//          [--wireframe] [--show-cells] [--show-control] [--preset blender|stylus]
//          [--ui-scale S] [--size WxH] [--quit-after SECONDS] [--bench N]
//          [--headless [--screenshot OUT.png] [--out FINAL.vtk] [--frames N]
//           [--supersample 1|2|4] [--transparent] [--no-ui]
//           [--record-seconds T [--fps F] --record-out OUT ...]]

#include <optional>
#include <string>
#include <vector>

#include "sculpt/display_settings.h"

namespace sculpt::app {

struct Options {
  /// Project (.sculpt), control mesh (.json) or surface (.obj/.gltf/.glb); empty: the bunny.
  std::string scene;
  std::string script;  ///< a session script to replay once the simulation runs
  std::optional<int> level;  ///< simulation level K
  std::optional<int> cage;   ///< cage cells across a surface scene
  std::optional<double> timeStep;  ///< seconds per step (over the scene's or project's)
  DisplaySettings display;
  bool stylusPreset = false;
  bool simulatedDevice = false;  ///< start with the mouse driving the mock haptic stylus
  bool showHelp = false;  ///< open the keys-and-mouse overlay at start
  float uiScale = 0.0f;  ///< 0: from the monitor's content scale
  bool headless = false;
  int frames = 60;
  std::string screenshot;
  std::string out;  ///< headless: the final control mesh (.vtk), as sculpt-cli simulate writes it
  int supersample = 1;
  bool transparent = false;
  bool noUi = false;  ///< headless: the 3D view alone, without panels
  int width = 1280, height = 800;
  bool sizeGiven = false;  ///< --size given (else the window takes its saved size)
  double quitAfter = 0.0;  ///< window mode: close this long after the first frame with the scene
  int benchFrames = 0;     ///< headless: time N frames (sculpt --bench) instead of a screenshot
  double recordSeconds = 0.0;  ///< headless: record this much simulated time (0: no recording)
  double recordFps = 30.0;     ///< frames per simulated second of a take (the window's too)
  std::vector<std::string> recordOut;  ///< headless: the take's outputs (the name picks the format)
};

extern const char* const kUsage;

/// Parses argv; throws std::invalid_argument with a sentence for a bad option. Prints the usage
/// and sets *helpShown for --help.
Options parseOptions(int argc, char** argv, bool* helpShown);

}  // namespace sculpt::app
