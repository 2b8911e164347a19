#include "sculpt/record_panel.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <string>

#include "anim/take_surface.h"
#include "sculpt/file_browser.h"
#include "sculpt/value_slider.h"

namespace sculpt::app {
namespace {

constexpr std::array<ExportFormat, kExportFormatCount> kFormats{
    ExportFormat::Glb,         ExportFormat::Pc2,         ExportFormat::Mdd,
    ExportFormat::ObjSequence, ExportFormat::VtkSequence, ExportFormat::VtuSequence,
    ExportFormat::PngSequence, ExportFormat::Mp4};
constexpr std::array<const char*, kExportFormatCount> kSuffixes{
    ".glb", ".pc2", ".mdd", "_####.obj", "_####.vtk", "_####.vtu", "_####.png", ".mp4"};

float scaled(float pixels) { return pixels * ImGui::GetFontSize() / 13.0f; }


ImU32 markColour(const char* type) {
  const std::string t(type);
  if (t == "grab") return IM_COL32(90, 160, 255, 255);
  if (t == "curve") return IM_COL32(60, 210, 220, 255);
  if (t == "inflate") return IM_COL32(255, 150, 50, 255);
  if (t == "paint") return IM_COL32(110, 220, 90, 255);
  return IM_COL32(200, 140, 255, 255);  // pin
}

// The take's strokes on the timeline slider just drawn: a bar for a stroke that lasts (grab,
// curve, inflate), a tick for an instant (dab, pin), at the frames the slider's grab stands on.
void drawTimelineMarks(const RecordStatus& s, int lastFrame) {
  if (s.marks.empty() || lastFrame <= 0 || s.takeFps <= 0) return;
  const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
  // ImGui's slider: 2 px padding, a grab as wide as one value (at least GrabMinSize).
  const float padding = 2.0f, travel = hi.x - lo.x - 2.0f * padding;
  const float grab =
      std::max(travel / static_cast<float>(lastFrame + 1), ImGui::GetStyle().GrabMinSize);
  const float x0 = lo.x + padding + 0.5f * grab, usable = std::max(1.0f, travel - grab);
  const auto x = [&](double seconds) {
    const double f = std::clamp(seconds * s.takeFps / lastFrame, 0.0, 1.0);
    return x0 + static_cast<float>(f) * usable;
  };
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float top = hi.y - 0.3f * (hi.y - lo.y), bottom = hi.y - 1.0f;
  for (const TimelineMark& mark : s.marks) {
    const float a = x(mark.start), b = std::max(x(mark.end), a + 2.0f);
    draw->AddRectFilled(ImVec2(a, top), ImVec2(b, bottom), markColour(mark.type));
  }
  if (ImGui::IsItemHovered()) {
    std::string counts;
    for (const char* type : {"grab", "curve", "inflate", "paint", "pin"}) {
      const auto n = std::count_if(s.marks.begin(), s.marks.end(), [type](const TimelineMark& m) {
        return std::string(m.type) == type;
      });
      if (n > 0) counts += (counts.empty() ? "" : ", ") + std::to_string(n) + " " + type;
    }
    ImGui::SetTooltip("Strokes of the take: %s\nFile > Save take script keeps them for "
                      "sculpt-cli record --script",
                      counts.c_str());
  }
}

}  // namespace

// (No "##" in these: ImGui would hide the rest of the label.)
const char* const kExportFormatLabels[kExportFormatCount] = {
    "glTF morph animation (.glb)",
    "Blender point cache (.pc2)",
    "LightWave point cache (.mdd)",
    "OBJ sequence (name_0001.obj, ...)",
    "VTK sequence (name_0001.vtk, ...)",
    "VTU + PVD (name_0001.vtu, ...)",
    "PNG frames of the view (name_0001.png, ...)",
    "H.264 video of the view (.mp4)"};

ExportFormat exportFormatAt(int index) {
  return kFormats[static_cast<size_t>(std::clamp(index, 0, kExportFormatCount - 1))];
}
const char* exportSuffix(int index) {
  return kSuffixes[static_cast<size_t>(std::clamp(index, 0, kExportFormatCount - 1))];
}

void setExportPath(ExportDialog& dialog, const std::string& path) {
  const size_t n = std::min(path.size(), dialog.path.size() - 1);
  std::copy_n(path.begin(), n, dialog.path.begin());
  dialog.path[n] = 0;
}

int exportFormatIndex(ExportFormat format) {
  const auto it = std::find(kFormats.begin(), kFormats.end(), format);
  return it == kFormats.end() ? 0 : static_cast<int>(it - kFormats.begin());
}

std::string withExportSuffix(const std::string& path, int index) {
  std::string base = path;
  for (const char* suffix : kSuffixes) {
    const std::string s(suffix);
    if (base.size() >= s.size() && base.compare(base.size() - s.size(), s.size(), s) == 0) {
      base.resize(base.size() - s.size());
      break;
    }
  }
  if (base.size() == path.size()) {  // another ending: drop a plain extension
    const size_t slash = base.find_last_of('/'), dot = base.find_last_of('.');
    if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) base.resize(dot);
  }
  return base + exportSuffix(index);
}

std::string byteSize(uint64_t bytes) {
  char text[32];
  if (bytes < 1024)
    std::snprintf(text, sizeof text, "%llu B", static_cast<unsigned long long>(bytes));
  else if (bytes < 1024 * 1024)
    std::snprintf(text, sizeof text, "%.1f KiB", static_cast<double>(bytes) / 1024.0);
  else
    std::snprintf(text, sizeof text, "%.1f MiB", static_cast<double>(bytes) / (1024.0 * 1024.0));
  return text;
}

void drawRecordStrip(AppModel& m) {
  RecordStatus& s = m.record;
  RecordRequests& r = m.requests.record;
  const float row = ImGui::GetFrameHeight();
  if (s.recording) {
    if (ImGui::Button("Stop", ImVec2(scaled(64), 0))) r.toggleRecord = true;
    ImGui::SameLine();
    // The red dot: recording now.
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImGui::GetWindowDrawList()->AddCircleFilled(ImVec2(at.x + 0.5f * row, at.y + 0.5f * row),
                                                0.3f * row, IM_COL32(230, 40, 40, 255));
    ImGui::Dummy(ImVec2(row, row));
    ImGui::SameLine();
    ImGui::Text("REC %u frames, %.2f s, %s, %zu stroke events", s.frames, s.seconds,
                byteSize(s.bytes).c_str(), s.strokes);
    return;
  }
  // A rendered export drives the playhead: the row waits for it.
  ImGui::BeginDisabled(m.exportDialog.rendering);
  if (ImGui::Button("Record", ImVec2(scaled(64), 0))) r.toggleRecord = true;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Record the running simulation (R)");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(scaled(70));
  double fps = s.fps;
  const double lo = 1.0, hi = 240.0;
  if (ImGui::DragScalar("##fps", ImGuiDataType_Double, &fps, 0.5f, &lo, &hi, "%.0f fps",
                        ImGuiSliderFlags_AlwaysClamp))
    s.fps = fps;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Frames per second of simulated time");
  ImGui::SameLine();
  ImGui::BeginDisabled(!s.hasTake);
  if (ImGui::Button(s.playingBack ? "Pause##take" : "Play##take", ImVec2(scaled(52), 0)))
    r.togglePlayback = true;
  ImGui::SameLine();
  ImGui::BeginDisabled(s.live);
  if (ImGui::Button("Live")) r.goLive = true;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Back to the running simulation");
  ImGui::EndDisabled();
  ImGui::SameLine();
  const std::string info =
      s.hasTake ? (s.live ? "live" : "frame " + std::to_string(s.playhead + 1)) + " of " +
                      std::to_string(s.frames) + " | " + byteSize(s.bytes)
                : std::string("no take yet");
  const float infoWidth = ImGui::CalcTextSize(info.c_str()).x + ImGui::GetStyle().ItemSpacing.x;
  ImGui::SetNextItemWidth(std::max(scaled(80), ImGui::GetContentRegionAvail().x - infoWidth));
  int frame = static_cast<int>(s.live ? (s.frames > 0 ? s.frames - 1 : 0) : s.playhead);
  const int last = std::max(0, static_cast<int>(s.frames) - 1);
  char label[48];
  std::snprintf(label, sizeof label, "%.2f s", s.takeFps > 0 ? frame / s.takeFps : 0.0);
  if (valueSliderInt("##timeline", &frame, 0, last, label, ImGuiSliderFlags_AlwaysClamp))
    r.playhead = static_cast<uint32_t>(frame);
  drawTimelineMarks(s, last);
  ImGui::SameLine();
  ImGui::TextUnformatted(info.c_str());
  ImGui::EndDisabled();
  ImGui::EndDisabled();
}

void drawExportDialog(AppModel& m) {
  ExportDialog& d = m.exportDialog;
  if (!d.show) return;
  RecordRequests& r = m.requests.record;
  ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing,
                          ImVec2(0.5f, 0.5f));
  if (!ImGui::Begin("Export recording", &d.show,
                    ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                        ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  ImGui::BeginDisabled(d.running);
  ImGui::SetNextItemWidth(scaled(420));
  if (ImGui::Combo("Format", &d.format, kExportFormatLabels, kExportFormatCount))
    setExportPath(d, withExportSuffix(std::string(d.path.data()), d.format));
  const float browseWidth =
      ImGui::CalcTextSize("Browse...").x + 2 * ImGui::GetStyle().FramePadding.x;
  ImGui::SetNextItemWidth(scaled(420) - browseWidth - ImGui::GetStyle().ItemInnerSpacing.x);
  ImGui::InputText("##file", d.path.data(), d.path.size());
  ImGui::SameLine(0, ImGui::GetStyle().ItemInnerSpacing.x);
  // The browser opens at the top level next frame (a modal opened inside this window would
  // belong to it) and writes the chosen path back into the field.
  if (ImGui::Button("Browse..."))
    openFileBrowser(m.fileBrowser, FileBrowserUse::Export, std::string(d.path.data()),
                    exportSuffix(d.format));
  ImGui::SameLine(0, ImGui::GetStyle().ItemInnerSpacing.x);
  ImGui::TextUnformatted("File");
  const int frames = static_cast<int>(std::max<uint32_t>(m.record.frames, 1));
  ImGui::SetNextItemWidth(scaled(120));
  ImGui::InputInt("First frame", &d.first);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(scaled(120));
  ImGui::InputInt("Last frame", &d.last);
  d.first = std::clamp(d.first, 1, frames);
  d.last = std::clamp(d.last, d.first, frames);
  ImGui::SetNextItemWidth(scaled(120));
  ImGui::InputInt("Every n-th frame", &d.every);
  d.every = std::clamp(d.every, 1, frames);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Export every n-th recorded frame: the take's frame rate divided by n");
  if (exportFormatAt(d.format) == ExportFormat::Glb) {
    ImGui::SetNextItemWidth(scaled(120));
    ImGui::InputDouble("Key tolerance", &d.keyTolerance, 0, 0, "%.2g");
    d.keyTolerance = std::clamp(d.keyTolerance, 0.0, 1.0);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("A frame becomes a key when it differs from the curve through the keys "
                        "by more than this part of the bounding-box diagonal");
  }
  ImGui::EndDisabled();
  ImGui::Text(
      "%u frames at %.4g fps, about %s",
      framesEvery(static_cast<uint32_t>(d.last - d.first + 1), static_cast<uint32_t>(d.every)),
      m.record.takeFps / d.every, byteSize(d.estimateBytes).c_str());
  if (!d.problem.empty())
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", d.problem.c_str());
  if (d.running) {
    ImGui::ProgressBar(static_cast<float>(d.fraction), ImVec2(scaled(420), 0));
    if (d.rendering)
      ImGui::TextDisabled("The view shows each frame as it is rendered.");
    else if (m.status.playing)  // the export only takes cores the simulation and the view leave
      ImGui::TextDisabled("The simulation is running: pause it for a faster export.");
    if (ImGui::Button("Cancel")) r.cancelExport = true;
  } else {
    ImGui::BeginDisabled(!d.problem.empty());
    if (ImGui::Button("Export")) r.startExport = true;
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Close")) d.show = false;
  }
  ImGui::End();
}

}  // namespace sculpt::app
