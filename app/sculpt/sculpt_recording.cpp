// SculptApp: recording the running simulation, the timeline's playback (the view shows a
// recorded frame instead of the newest simulated one) and the export dialog's worker.

#include <algorithm>
#include <filesystem>
#include <string>

#include "tools/session_script_writer.h"
#include "anim/take_playback.h"
#include "anim/take_surface.h"
#include "sculpt/app_clock.h"
#include "sculpt/record_panel.h"
#include "sculpt/sculpt_app.h"
#include "util/shell_command.h"

namespace sculpt::app {
namespace {

std::string exportedFiles(const ExportJob::Outcome& outcome) {
  const std::vector<std::filesystem::path>& files = outcome.result.files;
  if (files.size() <= 1) return (files.empty() ? outcome.path : files.front()).string();
  return std::to_string(files.size()) + " files " + files.front().string() + " ...";
}

// The dialog's 1-based inclusive range as a take range.
FrameRange exportRange(const ExportDialog& d) {
  return FrameRange{static_cast<uint32_t>(d.first - 1),
                    static_cast<uint32_t>(d.last - d.first + 1)};
}

}  // namespace

void SculptApp::leaveLive() {
  if (!recording_->isLive()) return;
  // Reviewing a take pauses the simulation; Live resumes what was running.
  resumePlaying_ = controller_->loop().playing();
  controller_->loop().setPlaying(false);
}

void SculptApp::goLive() {
  if (recording_->isLive()) return;
  recording_->goLive();
  controller_->loop().setPlaying(resumePlaying_);
}

void SculptApp::carryOutRecordRequests(const RecordRequests& r) {
  const Recording::Clock::time_point now = Recording::Clock::now();
  // A rendered export drives the playhead until it ends: the timeline waits.
  const bool rendering = rendered_.has_value();
  if (r.toggleRecord && rendering)
    model_.toast("an export is rendering: wait for it or cancel it", true);
  if (r.toggleRecord && !rendering) {
    sceneChanged_ = true;
    if (recording_->recording()) {
      recording_->stop();
    } else if (!latest_.physicsReady) {
      model_.toast("nothing to record until the simulation runs", true);
    } else {
      try {
        goLive();
        recording_->setFps(model_.record.fps);
        recording_->start(controller_->loop());
      } catch (const std::invalid_argument& error) {
        model_.toast(error.what(), true, 8.0);
      }
    }
  }
  const bool reviewable = !rendering && !recording_->recording() && recording_->take();
  if (reviewable && r.playhead) {
    leaveLive();
    recording_->setPlayhead(*r.playhead);
  }
  if (reviewable && r.togglePlayback) {
    if (recording_->playingBack()) {
      recording_->pause();
    } else {
      leaveLive();
      recording_->play(now);
    }
  }
  if (r.goLive && !rendering) goLive();
  if (r.startExport) startExport();
  if (r.cancelExport && rendering) {
    rendered_.reset();  // removes the frames written so far
    ExportJob::Outcome cancelled;
    cancelled.kind = ExportJob::Outcome::Kind::Cancelled;
    finishExport(std::move(cancelled));
  } else if (r.cancelExport) {
    export_->cancel();
  }
  if (r.saveScript) {
    // Beside the export path: take.glb -> take_script.json, for sculpt-cli record --script.
    std::filesystem::path path(model_.exportDialog.path.data());
    path.replace_filename(path.stem().string() + "_script.json");
    try {
      saveSessionScript(recording_->strokes().script(), path,
                        "strokes of a take made in the window");
      model_.toast("wrote " + path.string());
    } catch (const std::exception& error) {
      model_.toast(error.what(), true, 8.0);
    }
  }
  showPlayhead();  // the next frame draws what was asked for
  publishRecordStatus();
}

void SculptApp::showPlayhead() {
  const std::shared_ptr<const Take>& take = recording_->take();
  if (recording_->isLive() || !take) {
    if (!shownTake_) return;
    // Back to the simulation: its scene and its newest frame.
    shownTake_ = nullptr;
    if (liveGeometry_ && view_.sharedGeometry() != liveGeometry_) view_.setGeometry(liveGeometry_);
    if (latest_.sceneId == (view_.geometry() ? view_.geometry()->sceneId : 0))
      view_.setFrame(latest_, model_.display);
    sceneChanged_ = true;
    return;
  }
  const uint32_t frame = recording_->playhead();
  if (shownTake_ == take.get() && shownFrame_ == frame && shownGeometry_ == view_.geometry())
    return;
  const TakeSegment& segment = take->segments()[take->segmentOf(frame)];
  // A frame from before a rebuild shows the scene it was recorded on.
  if (view_.sharedGeometry() != segment.surface->sharedGeometry())
    view_.setGeometry(segment.surface->sharedGeometry());
  SceneFrame shown;
  playbackFrame(*take, frame, shown);
  shown.version = latest_.version;
  view_.setFrame(shown, model_.display);
  shownTake_ = take.get();
  shownFrame_ = frame;
  shownGeometry_ = view_.geometry();
  sceneChanged_ = true;
}

void SculptApp::publishRecordStatus() {
  RecordStatus& s = model_.record;
  s.recording = recording_->recording();
  s.frames = recording_->frameCount();
  s.seconds = recording_->seconds();
  s.bytes = recording_->memoryBytes();
  s.hasTake = recording_->take() != nullptr;
  s.takeFps = s.hasTake ? recording_->take()->fps() : recording_->fps();
  s.live = recording_->isLive();
  s.playhead = recording_->playhead();
  s.playingBack = recording_->playingBack();
  const SessionScript& strokes = recording_->strokes().script();
  s.marks.clear();  // rebuilt each frame: a stroke in progress grows
  for (const ScriptEvent& event : strokes.events)
    s.marks.push_back({event.time, event.endTime(), event.typeName()});
  s.strokes = strokes.events.size();
  if (s.recording || s.playingBack || rendered_) sceneChanged_ = true;  // keep drawing meanwhile
}

void SculptApp::updateRecording() {
  if (recording_->recording() && recording_->full()) {
    recording_->stop();
    model_.toast("the take is full (" + std::to_string(kMaxTakeFrames) +
                 " frames): recording stopped");
  }
  recording_->advance(Recording::Clock::now());
  showPlayhead();
  publishRecordStatus();

  if (std::optional<ExportJob::Outcome> outcome = export_->poll())
    finishExport(std::move(*outcome));
  updateExportDialog();
}

void SculptApp::finishExport(ExportJob::Outcome outcome) {
  switch (outcome.kind) {
    case ExportJob::Outcome::Kind::Written:
      model_.toast("wrote " + exportedFiles(outcome) + " (" + byteSize(outcome.result.bytes) + ")",
                   false, 8.0);
      break;
    case ExportJob::Outcome::Kind::Failed: model_.toast(outcome.error, true, 10.0); break;
    case ExportJob::Outcome::Kind::Cancelled:
      model_.toast("Export cancelled; nothing was written");
      break;
  }
  lastExport_ = std::move(outcome);
}

void SculptApp::renderExportFrame() {
  if (!rendered_ ||
      recording_->playhead() != rendered_->range.first + rendered_->next * rendered_->every)
    return;
  RenderedExport& r = *rendered_;
  ExportJob::Outcome outcome;
  outcome.path = r.path;
  try {
    // The 3D view alone, as a screenshot without panels takes it.
    ScreenshotSettings settings = model_.screenshot;
    settings.includePanels = false;
    int width = 0, height = 0;
    const std::vector<uint8_t> pixels = captureFrame(settings, width, height);
    r.out->write(++r.next, pixels, width, height);
    if (r.next < r.count) {
      recording_->setPlayhead(r.range.first + r.next * r.every);  // the next window frame's
      return;
    }
    outcome.result.frames = r.count;
    outcome.result.bytes = r.out->finish();
    outcome.result.files = r.out->files();
  } catch (const std::exception& error) {
    outcome.kind = ExportJob::Outcome::Kind::Failed;
    outcome.error = r.path.string() + ": " + error.what();
  }
  rendered_.reset();  // a failed export's files go with it
  finishExport(std::move(outcome));
}

std::string SculptApp::defaultExportPath() const {
  // Next to the scene: <scene stem>_take.glb (the default bunny: in the working folder).
  const std::filesystem::path scene = model_.sceneFile;
  std::string stem = scene.empty() ? "bunny" : scene.stem().string();
  if (std::filesystem::path(stem).extension() == ".sculpt")
    stem = std::filesystem::path(stem).stem().string();
  return (scene.parent_path() / (stem + "_take")).string() + exportSuffix(0);
}

void SculptApp::updateExportDialog() {
  ExportDialog& d = model_.exportDialog;
  d.running = exporting();
  d.rendering = rendered_.has_value();
  d.fraction =
      rendered_ ? static_cast<double>(rendered_->next) / rendered_->count : export_->fraction();
  const std::shared_ptr<const Take>& take = recording_->take();
  if (d.path[0] == 0) setExportPath(d, withExportSuffix(defaultExportPath(), d.format));
  if (take.get() != dialogTake_) {  // a new take: all of it
    dialogTake_ = take.get();
    d.first = 1;
    d.last = take ? static_cast<int>(take->frameCount()) : 1;
    estimatedFormat_ = -1;
  }
  if (!d.show && !model_.requests.record.startExport) return;
  const std::string path(d.path.data());
  const ExportTarget target = exportTargetFor(path);
  d.problem = target.problem;
  if (d.problem.empty() && target.format)
    d.format = exportFormatIndex(*target.format);  // the name decides the format
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  std::error_code ignored;
  if (d.problem.empty() && !parent.empty() && !std::filesystem::is_directory(parent, ignored))
    d.problem = "the folder " + parent.string() + " does not exist";
  if (!take && d.problem.empty()) d.problem = "nothing recorded yet";
  static const bool ffmpegFound = programOnPath("ffmpeg");  // once: this runs every frame
  if (d.problem.empty() && exportFormatAt(d.format) == ExportFormat::Mp4 && !ffmpegFound)
    d.problem = "writing .mp4 needs the ffmpeg program (scripts/install-deps.sh installs it)";
  if (!take || d.running) return;
  // The estimate, once per range and format (a TakeSurface is cheap, but not free every frame).
  if (d.first == estimatedFirst_ && d.last == estimatedLast_ && d.every == estimatedEvery_ &&
      d.format == estimatedFormat_)
    return;
  estimatedFirst_ = d.first, estimatedLast_ = d.last, estimatedEvery_ = d.every;
  estimatedFormat_ = d.format;
  try {
    const TakeSurface surface(take, exportRange(d), static_cast<uint32_t>(d.every));
    d.estimateBytes = estimateExportBytes(surface, exportFormatAt(d.format));
  } catch (const std::exception& error) {
    d.estimateBytes = 0;
    d.problem = error.what();
  }
}

bool SculptApp::startExport() {
  ExportDialog& d = model_.exportDialog;
  const bool shown = d.show;
  d.show = true;  // the checks run for the dialog, shown or not
  estimatedFormat_ = -1;
  updateExportDialog();
  d.show = shown;
  const std::shared_ptr<const Take>& take = recording_->take();
  std::string refusal;
  if (exporting())
    refusal = "an export is running already: wait for it or cancel it";
  else if (!d.problem.empty())
    refusal = d.problem;
  if (!refusal.empty() || !take) {
    model_.toast(refusal.empty() ? "nothing recorded yet" : refusal, true, 8.0);
    return false;
  }
  const ExportFormat format = exportFormatAt(d.format);
  if (isRenderedFormat(format)) {
    RenderedExport r;
    r.path = std::string(d.path.data());
    r.range = exportRange(d);
    r.every = static_cast<uint32_t>(d.every);
    r.count = framesEvery(r.range.count, r.every);
    try {
      std::vector<std::filesystem::path> pngs, videos;
      (format == ExportFormat::Mp4 ? videos : pngs).push_back(r.path);
      r.out = std::make_unique<RenderedFrames>(pngs, videos, take->fps() / r.every);
    } catch (const std::exception& error) {
      model_.toast(error.what(), true, 8.0);
      return false;
    }
    leaveLive();
    recording_->setPlayhead(r.range.first);
    rendered_ = std::move(r);
    d.running = true;
    d.fraction = 0.0;
    return true;
  }
  TakeExportOptions options;
  options.keyTolerance = d.keyTolerance;
  if (!export_->start(take, exportRange(d), static_cast<uint32_t>(d.every),
                      std::string(d.path.data()), format, options))
    return false;
  d.running = true;
  d.fraction = 0.0;
  return true;
}

}  // namespace sculpt::app
