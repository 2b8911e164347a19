// SculptApp: session scripts replayed in the window (File > Replay session script, --script).
// Topology events are applied to the document's control mesh first, as the script's starting
// state; the rest of the script plays on the simulation loop once that scene is built.

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "io/file_error.h"
#include "project/project.h"
#include "sculpt/sculpt_app.h"
#include "tools/script_topology.h"
#include "tools/session_script.h"

namespace sculpt::app {

void SculptApp::startScript(SessionScript script, bool documentReady) {
  if (!hasTopologyEvents(script)) {
    controller_->loop().playScript(std::move(script));
    return;
  }
  scriptTopology_ = std::move(script);
  if (documentReady) applyScriptTopology();  // else when the first scene arrives
}

void SculptApp::replayScript(const std::string& path) {
  try {
    SessionScript script = loadSessionScript(path);
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.3g s", script.duration());
    model_.toast("replaying " + std::filesystem::path(path).filename().string() + " (" + seconds +
                 ")");
    scriptPath_ = path;
    startScript(std::move(script), true);
  } catch (const FileError& error) {
    model_.toast(error.what(), true, 8.0);
  }
}

void SculptApp::applyScriptTopology() {
  SessionScript script = *std::exchange(scriptTopology_, std::nullopt);
  Project edited = document_.project();
  try {
    edited.controlMesh = applyTopologyEvents(edited.controlMesh, script);
  } catch (const std::invalid_argument& error) {
    const std::string message = scriptPath_ + ": " + error.what();
    std::cerr << "error: " << message << '\n';
    model_.toast(message, true, 10.0);
    return;
  }
  // Pins follow their points by position (surviving vertices keep their positions exactly).
  const Project& original = document_.project();
  std::vector<uint32_t> pins;
  for (const uint32_t v : original.pins)
    for (uint32_t w = 0; w < edited.controlMesh.numVertices(); ++w)
      if (edited.controlMesh.positions.row(w) == original.controlMesh.positions.row(v)) {
        pins.push_back(w);
        break;
      }
  normalisePins(pins);
  edited.pins = std::move(pins);
  document_.start(std::move(edited));  // the script's starting state, not an undoable edit
  storeSettingsInProject();
  deferredScript_ = std::move(script);
  awaitingEditedScene_ = true;
  loadDocumentScene();
}

}  // namespace sculpt::app
