#pragma once
// What the panels see of recording, the timeline and the export dialog, and what they ask for
// (the application carries it out after the UI pass, as with Requests).

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace sculpt::app {

/// The formats the export dialog offers, in its combo's order: geometry, then rendered frames.
inline constexpr int kExportFormatCount = 8;
extern const char* const kExportFormatLabels[kExportFormatCount];

struct RecordRequests {
  bool toggleRecord = false;
  std::optional<uint32_t> playhead;  ///< scrub to this frame (leaves Live)
  bool togglePlayback = false, goLive = false;
  bool startExport = false, cancelExport = false;
  bool saveScript = false;  ///< the take's strokes as a session script beside the export path
};

/// A stroke of the take as the timeline marks it: when it acts (an instant for a dab or a pin)
/// and the script event type it was captured as ("grab", "inflate", "paint", "pin", "curve").
struct TimelineMark {
  double start = 0, end = 0;  ///< s of take time
  const char* type = "";
};

struct RecordStatus {
  double fps = 30.0;  ///< the next take's frame rate (a setting)
  bool recording = false;
  uint32_t frames = 0;  ///< of the take being recorded, or of the last take
  double seconds = 0.0;
  size_t bytes = 0;
  bool hasTake = false;  ///< a stopped take with frames exists
  double takeFps = 30.0;
  bool live = true;        ///< the view shows the running simulation
  uint32_t playhead = 0;   ///< the frame shown when not live
  bool playingBack = false;
  size_t strokes = 0;  ///< script events captured in the take
  std::vector<TimelineMark> marks;  ///< of those events, in time order
};

struct ExportDialog {
  bool show = false;
  int format = 0;  ///< index into kExportFormatLabels
  std::array<char, 1024> path{};
  int first = 1, last = 1;  ///< frame range, 1-based and inclusive as shown
  int every = 1;            ///< every n-th frame of the range: the take's fps / n
  double keyTolerance = 1e-3;  ///< glTF: of the rest bounding-box diagonal
  // Filled by the application each frame
  std::string problem;        ///< why Export is not allowed now; empty: it is
  uint64_t estimateBytes = 0;
  bool running = false;
  bool rendering = false;  ///< a PNG or video export: the view plays the frames it renders
  double fraction = 0.0;
};

}  // namespace sculpt::app
