#include "sculpt/panels.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include "sculpt/colour_bar.h"
#include "sculpt/file_browser.h"
#include "sculpt/real_time_factor.h"
#include "sculpt/record_panel.h"
#include "sculpt/tool_panel.h"
#include "sculpt/value_slider.h"

namespace sculpt::app {
namespace {

constexpr ImGuiWindowFlags kPanelFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                         ImGuiWindowFlags_NoCollapse |
                                         ImGuiWindowFlags_NoSavedSettings |
                                         ImGuiWindowFlags_NoBringToFrontOnFocus;

const ImVec4 kAmber(1.0f, 0.72f, 0.2f, 1.0f);
constexpr double kCageMin = 3.0, kCageMax = 16.0, kPoissonMin = 0.0, kPoissonMax = 0.49;

float scaled(float pixels) { return pixels * ImGui::GetFontSize() / 13.0f; }

// A menu entry's shortcut column: ImGui leaves one item spacing before it, which long entries
// ("Undo Paint Young's modulus") run into; three spaces more keep the shortcuts apart.
std::string keys(const char* shortcut) { return std::string("   ") + shortcut; }

void menuBar(AppModel& m) {
  if (!ImGui::BeginMainMenuBar()) return;
  Requests& r = m.requests;
  bool openSaveAs = false;
  if (ImGui::BeginMenu("File")) {
    if (ImGui::MenuItem("New (default bunny)")) r.loadScene = "<default>";
    if (ImGui::MenuItem("Open...", keys("Ctrl+O").c_str())) m.openOpenDialog = true;
    if (ImGui::MenuItem("Import surface..."))
      openFileBrowser(m.fileBrowser, FileBrowserUse::ImportSurface, std::string());
    if (ImGui::MenuItem("Save", keys("Ctrl+S").c_str())) r.save = true;
    if (ImGui::MenuItem("Save As...", keys("Ctrl+Shift+S").c_str())) openSaveAs = true;
    ImGui::Separator();
    if (ImGui::BeginMenu("Recent files", !m.recentScenes.empty())) {
      for (const std::string& path : m.recentScenes)
        if (ImGui::MenuItem(path.c_str())) r.loadScene = path;
      ImGui::EndMenu();
    }
    if (ImGui::MenuItem("Replay session script..."))
      openFileBrowser(m.fileBrowser, FileBrowserUse::ReplayScript, std::string());
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "Plays a script's pulls, paint, pins and inflation on the scene shown "
          "(docs/file-formats.md); its topology events edit the cage first.");
    if (ImGui::MenuItem("Export recording...", nullptr, false,
                        m.record.hasTake && !m.record.recording))
      m.exportDialog.show = true;
    if (ImGui::MenuItem("Save take script", nullptr, false,
                        m.record.hasTake && !m.record.recording && m.record.strokes > 0))
      r.record.saveScript = true;
    if (ImGui::MenuItem("Screenshot", keys("F12").c_str())) r.screenshot = true;
    if (ImGui::BeginMenu("Screenshot options")) {
      ImGui::RadioButton("1x", &m.screenshot.supersample, 1);
      ImGui::SameLine();
      ImGui::RadioButton("2x", &m.screenshot.supersample, 2);
      ImGui::SameLine();
      ImGui::RadioButton("4x", &m.screenshot.supersample, 4);
      ImGui::Checkbox("Transparent background", &m.screenshot.transparent);
      ImGui::Checkbox("Include panels", &m.screenshot.includePanels);
      ImGui::EndMenu();
    }
    ImGui::Separator();
    if (ImGui::MenuItem("Quit", keys("Ctrl+Q").c_str())) r.quit = true;
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Edit")) {
    const std::string undo = "Undo " + m.document.undoLabel, redo = "Redo " + m.document.redoLabel;
    if (ImGui::MenuItem(undo.c_str(), keys("Ctrl+Z").c_str(), false, m.document.canUndo))
      r.undo = true;
    if (ImGui::MenuItem(redo.c_str(), keys("Ctrl+Shift+Z").c_str(), false, m.document.canRedo))
      r.redo = true;
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("View")) {
    if (ImGui::MenuItem("Frame model", keys("F").c_str())) r.frameModel = true;
    if (ImGui::MenuItem("Frame all", keys("Home").c_str())) r.frameAll = true;
    if (ImGui::MenuItem("Front", keys("Numpad 1").c_str()))
      r.standardView = render::StandardView::Front;
    if (ImGui::MenuItem("Right", keys("Numpad 3").c_str()))
      r.standardView = render::StandardView::Right;
    if (ImGui::MenuItem("Top", keys("Numpad 7").c_str()))
      r.standardView = render::StandardView::Top;
    if (ImGui::MenuItem("Perspective / orthographic", keys("Numpad 5").c_str()))
      r.toggleOrthographic = true;
    ImGui::Separator();
    ImGui::MenuItem("Panels", keys("Tab").c_str(), &m.showPanels);
    ImGui::MenuItem("Stylus device", nullptr, &m.showStylus);
    if (ImGui::BeginMenu("Navigation preset")) {
      if (ImGui::MenuItem("Blender (middle mouse)", nullptr, m.preset == NavigationPreset::Blender))
        m.preset = NavigationPreset::Blender;
      if (ImGui::MenuItem("Stylus (drag on background)", nullptr,
                          m.preset == NavigationPreset::Stylus))
        m.preset = NavigationPreset::Stylus;
      ImGui::EndMenu();
    }
    if (valueSliderFloat("UI scale", &m.uiScale, 1.0f, 3.0f, "%.2f")) r.uiScaleChanged = true;
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Simulation")) {
    if (ImGui::MenuItem(m.status.playing ? "Pause" : "Play", keys("Space").c_str()))
      r.togglePlay = true;
    if (ImGui::MenuItem("Step", keys(".").c_str())) r.stepOnce = true;
    if (ImGui::MenuItem("Reset", keys("Shift+R").c_str())) r.reset = true;
    if (ImGui::MenuItem(m.record.recording ? "Stop recording" : "Record", keys("R").c_str()))
      r.record.toggleRecord = true;
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Help")) {
    if (ImGui::MenuItem("Keys and mouse", keys("F1").c_str())) m.showHelp = true;
    ImGui::EndMenu();
  }
  // The window title is the document's; the menu bar repeats it for full-screen use.
  const std::string title = m.document.title;
  ImGui::SetCursorPosX(ImGui::GetWindowWidth() - ImGui::CalcTextSize(title.c_str()).x - scaled(12));
  ImGui::TextDisabled("%s", title.c_str());
  ImGui::EndMainMenuBar();
  if (openSaveAs || m.openSaveAsDialog) {
    m.openSaveAsDialog = false;
    // Beside the file shown, under the document's name ("untitled.sculpt" for a new one).
    const std::filesystem::path shown(m.sceneFile), name(m.document.name);
    openFileBrowser(m.fileBrowser, FileBrowserUse::SaveProject,
                    (shown.has_parent_path() ? shown.parent_path() / name : name).string());
  }
  if (m.openOpenDialog) {
    m.openOpenDialog = false;
    openFileBrowser(m.fileBrowser, FileBrowserUse::Open, std::string());
  }
}

// Modal dialogs: the file browser (Open, Import, Save As, the export path), unsaved changes on
// close, recovery after a crash.
void dialogs(AppModel& m) {
  Requests& r = m.requests;
  const ImVec2 centre = ImGui::GetMainViewport()->GetCenter();
  if (const std::optional<std::string> path = drawFileBrowser(m.fileBrowser, m.recentScenes)) {
    switch (m.fileBrowser.use) {
      case FileBrowserUse::Open:
      case FileBrowserUse::ImportSurface:
        r.loadScene = *path;
        break;
      case FileBrowserUse::SaveProject:
        r.saveAs = *path;
        break;
      case FileBrowserUse::Export:
        setExportPath(m.exportDialog, *path);
        break;
      case FileBrowserUse::ReplayScript:
        r.replayScript = *path;
        break;
    }
  }
  if (m.document.closePrompt) ImGui::OpenPopup("Unsaved changes");
  ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("Save changes to %s before closing?", m.document.name.c_str());
    if (ImGui::Button("Save")) {
      r.closeSave = true;
      m.document.closePrompt = false;
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Don't save")) {
      r.closeDiscard = true;
      m.document.closePrompt = false;
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) {
      m.document.closePrompt = false;
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }
  // (Not in the first frames: ImGui 1.86 asserts when windows appear for the first time behind a
  // modal opened in the same frame.)
  if (!m.document.recoveryOffer.empty() && ImGui::GetFrameCount() > 2)
    ImGui::OpenPopup("Recover unsaved work?");
  ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (ImGui::BeginPopupModal("Recover unsaved work?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    if (m.document.recoveryOffer.empty()) ImGui::CloseCurrentPopup();  // answered elsewhere
    ImGui::Text("The program did not close cleanly. Autosaved work was found:\n%s",
                m.document.recoveryOffer.c_str());
    if (ImGui::Button("Recover")) {
      r.recover = true;
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard")) {
      r.discardRecovery = true;
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }
}

void toolPanel(AppModel& m, ImVec2 pos, ImVec2 size) {
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowSize(size);
  ImGui::Begin("Tools", nullptr, kPanelFlags);
  Requests& r = m.requests;
  drawToolSettings(m);
  ImGui::Separator();
  ImGui::TextDisabled("Navigate");
  int preset = m.preset == NavigationPreset::Stylus ? 1 : 0;
  ImGui::RadioButton("Blender mouse", &preset, 0);
  ImGui::RadioButton("Stylus / pen", &preset, 1);
  m.preset = preset == 1 ? NavigationPreset::Stylus : NavigationPreset::Blender;
  ImGui::Separator();
  ImGui::TextDisabled("View");
  const float half = 0.5f * (ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemSpacing.x);
  if (ImGui::Button("Front", ImVec2(half, 0))) r.standardView = render::StandardView::Front;
  ImGui::SameLine();
  if (ImGui::Button("Right", ImVec2(half, 0))) r.standardView = render::StandardView::Right;
  if (ImGui::Button("Top", ImVec2(half, 0))) r.standardView = render::StandardView::Top;
  ImGui::SameLine();
  if (ImGui::Button("Ortho", ImVec2(half, 0))) r.toggleOrthographic = true;
  if (ImGui::Button("Frame model (F)", ImVec2(-1, 0))) r.frameModel = true;
  ImGui::Separator();
  if (ImGui::Button("Screenshot (F12)", ImVec2(-1, 0))) r.screenshot = true;
  if (ImGui::Button("Keys and mouse (F1)", ImVec2(-1, 0))) m.showHelp = true;
  ImGui::End();
}

void scenePanel(AppModel& m) {
  Requests& r = m.requests;
  SceneSettings& s = m.settings;
  if (ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen)) {
    ImGui::TextWrapped("%s", m.status.description.c_str());
    ImGui::InputTextWithHint("##path", "file.sculpt / .json / .obj / .glb", m.scenePathInput.data(),
                             m.scenePathInput.size());
    ImGui::SameLine();
    if (ImGui::Button("Load") && m.scenePathInput[0] != 0)
      r.loadScene = std::string(m.scenePathInput.data());
    bool rebuild = false;
    rebuild |= valueSliderInt("Level K", &s.level, 1, 3, "%d", ImGuiSliderFlags_AlwaysClamp);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Simulation level: elements live on the level-K cells (x8 per level)");
    if (!m.controlMeshScene)
      rebuild |=
          valueSliderDouble("Cage cells", &s.cageCellsAcross, kCageMin, kCageMax, "%.0f across");
    else
      rebuild |= valueSliderInt("Render level", &s.renderLevel, 1, 5);
    if (rebuild && !ImGui::IsItemActive()) r.applySettings = true;
    if (ImGui::IsItemDeactivatedAfterEdit()) r.applySettings = true;
  }
  if (ImGui::CollapsingHeader("Material", ImGuiTreeNodeFlags_DefaultOpen)) {
    bool changed = false;
    changed |= logValueSlider("Young's modulus", &s.material.youngs, 1e3, 1e9, "%.3g Pa");
    changed |=
        valueSliderDouble("Poisson ratio", &s.material.poisson, kPoissonMin, kPoissonMax, "%.3f");
    changed |= logValueSlider("Density", &s.material.density, 1.0, 1e5, "%.4g kg/m^3");
    changed |= logValueSlider("Damping", &s.material.damping, 0.01, 1e5, "%.3g kg/(m^3 s)");
    if (changed) r.applySettings = true;
  }
  if (ImGui::CollapsingHeader("Simulation", ImGuiTreeNodeFlags_DefaultOpen)) {
    int integrator = s.integrator == Integrator::Implicit ? 0 : 1;
    bool changed =
        ImGui::Combo("Integrator", &integrator, "Implicit (stable)\0Paper (CG, explicit)\0");
    s.integrator = integrator == 0 ? Integrator::Implicit : Integrator::Paper;
    int model = s.elasticModel == ElasticModel::Barrier ? 0 : 1;
    if (ImGui::Combo("Elastic model", &model, "Inversion barrier\0Co-rotated (paper)\0")) {
      s.elasticModel = model == 0 ? ElasticModel::Barrier : ElasticModel::Corotated;
      changed = true;
    }
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("The barrier pushes back parts squeezed below half their volume and turns "
                        "inverted ones back; both models agree until then.");
    double dtMs = s.timeStep * 1000.0;
    if (logValueSlider("Time step", &dtMs, 0.1, 100.0, "%.2f ms")) {
      s.timeStep = dtMs / 1000.0;
      changed = true;
    }
    float gravity[3] = {static_cast<float>(s.gravity.x()), static_cast<float>(s.gravity.y()),
                        static_cast<float>(s.gravity.z())};
    if (ImGui::DragFloat3("Gravity", gravity, 0.05f, -100.0f, 100.0f, "%.2f")) {
      s.gravity = Eigen::Vector3d(gravity[0], gravity[1], gravity[2]);
      changed = true;
    }
    if (changed) r.applySettings = true;
    if (ImGui::Button(m.status.playing ? "Pause" : "Play")) r.togglePlay = true;
    ImGui::SameLine();
    if (ImGui::Button("Step")) r.stepOnce = true;
    ImGui::SameLine();
    if (ImGui::Button("Reset")) r.reset = true;
  }
}

void displayPanel(AppModel& m) {
  DisplaySettings& d = m.display;
  if (!ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen)) return;
  int method = static_cast<int>(d.method);
  if (ImGui::Combo("Deformation", &method, "Linear\0Vertex\0Phong\0Attribute\0"))
    d.method = static_cast<InterpolationMethod>(method);
  const bool usesGradients =
      d.method == InterpolationMethod::Phong || d.method == InterpolationMethod::Vertex;
  ImGui::BeginDisabled(!usesGradients);
  int gradients = static_cast<int>(d.gradients);
  if (ImGui::Combo("Node gradients", &gradients, "Average (paper)\0Quadratic fit\0"))
    d.gradients = static_cast<GradientScheme>(gradients);
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip(
        "How each node's deformation gradient is found. Quadratic fit: third-order accurate on\n"
        "the surface too; Average: the paper's weighted average of cell gradients (eq. 12),\n"
        "one order less in the surface cells. Used by Phong and Vertex.");
  ImGui::EndDisabled();
  int field = static_cast<int>(d.field);
  if (ImGui::Combo("Field", &field,
                   "None\0Young's modulus\0Density\0Displacement\0Strain energy\0Damping\0"))
    d.field = static_cast<FieldKind>(field);
  if (d.field != FieldKind::None && d.field != FieldKind::Displacement) {
    // The cell fields: smooth through node values, or flat per level-K cell.
    int perCell = d.smoothField ? 0 : 1;
    ImGui::RadioButton("Smooth", &perCell, 0);
    ImGui::SameLine();
    ImGui::RadioButton("Per cell", &perCell, 1);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "Each level-K cell in one flat colour, its element's mean: to inspect\n"
          "the cells. Smooth interpolates node values, the cells' volume-weighted means.");
    d.smoothField = perCell == 0;
  }
  if (d.field != FieldKind::None) {
    ImGui::Checkbox("Automatic range", &d.autoRange);
    if (!d.autoRange) {
      ImGui::InputFloat("Low", &d.rangeLow, 0, 0, "%.4g");
      ImGui::InputFloat("High", &d.rangeHigh, 0, 0, "%.4g");
    }
  }
  ImGui::Checkbox("Surface", &d.showSurface);
  ImGui::SameLine();
  ImGui::Checkbox("Flat", &d.flatShading);
  ImGui::SameLine();
  ImGui::Checkbox("Wireframe", &d.wireframe);
  ImGui::Checkbox("Control mesh", &d.showControlMesh);
  ImGui::SameLine();
  ImGui::Checkbox("Cells by type", &d.showCells);
  if (d.showCells) {
    ImGui::TextColored(ImVec4(0.35f, 0.55f, 0.95f, 1), "tricubic");
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(0.95f, 0.55f, 0.15f, 1), "trilinear");
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(0.85f, 0.25f, 0.85f, 1), "pyramid");
  }
  ImGui::Checkbox("Grid", &d.showGrid);
  ImGui::SameLine();
  ImGui::Checkbox("Axes", &d.showAxes);
  ImGui::Checkbox("Clipping plane", &d.clip);
  if (d.clip) {
    ImGui::RadioButton("x", &d.clipAxis, 0);
    ImGui::SameLine();
    ImGui::RadioButton("y", &d.clipAxis, 1);
    ImGui::SameLine();
    ImGui::RadioButton("z", &d.clipAxis, 2);
    valueSliderFloat("Position", &d.clipPosition, 0.0f, 1.0f, "%.2f");
  }
}

void rightPanel(AppModel& m, ImVec2 pos, ImVec2 size) {
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowSize(size);
  ImGui::Begin("Properties", nullptr, kPanelFlags);
  ImGui::PushItemWidth(-scaled(110));
  scenePanel(m);
  displayPanel(m);
  ImGui::PopItemWidth();
  ImGui::End();
}

// The simulation against the clock: amber while it falls behind (a stylus would feel the lag).
void realTimeText(const Status& s) {
  if (!s.playing || !s.physicsReady || !s.realTimeFactor) {
    ImGui::TextDisabled("%s", s.playing ? "-- real time" : "paused");
    return;
  }
  const std::string label = realTimeLabel(*s.realTimeFactor);
  if (behindRealTime(*s.realTimeFactor))
    ImGui::TextColored(kAmber, "%s", label.c_str());
  else
    ImGui::TextUnformatted(label.c_str());
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Simulated seconds per second of the clock over the last second.%s",
                      behindRealTime(*s.realTimeFactor)
                          ? "\nBelow 1x the solid moves in slow motion: a coarser cage or a lower "
                            "level keeps up."
                          : "");
}

void bottomStrip(AppModel& m, ImVec2 pos, ImVec2 size) {
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowSize(size);
  ImGui::Begin("Status", nullptr,
               kPanelFlags | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar);
  Requests& r = m.requests;
  if (ImGui::Button(m.status.playing ? "Pause" : "Play", ImVec2(scaled(52), 0)))
    r.togglePlay = true;
  ImGui::SameLine();
  if (ImGui::Button("Step")) r.stepOnce = true;
  ImGui::SameLine();
  if (ImGui::Button("Reset")) r.reset = true;
  ImGui::SameLine();
  const Status& s = m.status;
  ImGui::Text("t %.2f s | sim %.1f ms/step (%.0f/s) |", s.simulatedTime, s.simulationMs,
              s.stepsPerSecond);
  ImGui::SameLine();
  realTimeText(s);
  ImGui::SameLine();
  // The rest as far as the strip has room (UI scale 2 on a small window), most telling first;
  // the whole line is the tooltip.
  char parts[4][96];
  std::snprintf(parts[0], sizeof parts[0], "| frame %.1f ms", s.frameMs);
  std::snprintf(parts[1], sizeof parts[1], "| 3D view %.2f ms GPU, upload %.0f KiB", s.sceneDrawMs,
                static_cast<double>(s.uploadBytes) / 1024.0);
  std::snprintf(parts[2], sizeof parts[2], "| %zu tris", s.triangles);
  std::snprintf(parts[3], sizeof parts[3], "| %u tricubic, %u trilinear, %u pyramid",
                s.elementCounts[0], s.elementCounts[1], s.elementCounts[2]);
  if (!s.physicsReady) {
    ImGui::TextUnformatted("| preparing physics");
    ImGui::SameLine();
  }
  std::string shown;
  for (const char* part : parts) {
    const std::string next = shown.empty() ? std::string(part) : shown + " " + part;
    if (ImGui::CalcTextSize(next.c_str()).x > ImGui::GetContentRegionAvail().x) break;
    shown = next;
  }
  ImGui::TextUnformatted(shown.c_str());
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("%s %s %s %s", parts[0], parts[1], parts[2], parts[3]);
  drawRecordStrip(m);
  ImGui::End();
}

}  // namespace

ViewRect drawPanels(AppModel& m) {
  menuBar(m);
  dialogs(m);
  drawExportDialog(m);
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImVec2 min = viewport->WorkPos;
  ImVec2 max(viewport->WorkPos.x + viewport->WorkSize.x,
             viewport->WorkPos.y + viewport->WorkSize.y);
  if (!m.showPanels) return {min, max};
  const float left = std::min(scaled(220), 0.3f * viewport->WorkSize.x);
  const float right = std::min(scaled(320), 0.35f * viewport->WorkSize.x);
  // Two rows: the simulation's buttons and status, then recording and the timeline.
  const float bottom =
      2 * ImGui::GetFrameHeightWithSpacing() + 2 * ImGui::GetStyle().WindowPadding.y;
  toolPanel(m, min, ImVec2(left, max.y - min.y - bottom));
  rightPanel(m, ImVec2(max.x - right, min.y), ImVec2(right, max.y - min.y - bottom));
  bottomStrip(m, ImVec2(min.x, max.y - bottom), ImVec2(max.x - min.x, bottom));
  return {ImVec2(min.x + left, min.y), ImVec2(max.x - right, max.y - bottom)};
}

void drawBuildProgress(AppModel& m, ViewRect view) {
  const BuildStatus& build = m.status.build;
  if (!build.running) return;
  const ImVec2 size(scaled(320), 0);
  ImGui::SetNextWindowPos(
      ImVec2(0.5f * (view.min.x + view.max.x), 0.5f * (view.min.y + view.max.y)), ImGuiCond_Always,
      ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(size);
  ImGui::Begin("Preparing", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::Text("%s", build.stage.empty() ? "Preparing..." : build.stage.c_str());
  ImGui::ProgressBar(static_cast<float>(build.fraction), ImVec2(-1, 0));
  if (ImGui::Button("Cancel", ImVec2(-1, 0))) m.requests.cancelBuild = true;
  ImGui::End();
}

void drawToasts(AppModel& m, ViewRect view) {
  const auto now = std::chrono::steady_clock::now();
  std::erase_if(m.toasts, [&](const Toast& t) { return t.until < now; });
  float y = view.min.y + scaled(10);
  const float wrapWidth =
      std::max(scaled(80), std::min(scaled(420), view.max.x - view.min.x - scaled(20) -
                                                     2.0f * ImGui::GetStyle().WindowPadding.x));
  int index = 0;
  for (const Toast& toast : m.toasts) {
    ImGui::SetNextWindowPos(ImVec2(view.max.x - scaled(10), y), ImGuiCond_Always,
                            ImVec2(1.0f, 0.0f));
    ImGui::SetNextWindowBgAlpha(0.8f);
    const std::string name = "##toast" + std::to_string(index++);
    ImGui::Begin(name.c_str(), nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                     ImGuiWindowFlags_NoNav);
    // Wrapped to the 3D view's width, so that a long message never covers a panel.
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + wrapWidth);
    if (toast.error) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
    ImGui::TextUnformatted(toast.text.c_str());
    if (toast.error) ImGui::PopStyleColor();
    ImGui::PopTextWrapPos();
    y += ImGui::GetWindowHeight() + scaled(6);
    ImGui::End();
  }
}

}  // namespace sculpt::app
