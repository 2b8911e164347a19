#pragma once
// The recording's part of the window: Record / Stop with the take's length, and the timeline
// (playhead slider, Play / Pause of the take, Live) in the bottom strip; the export dialog
// (format, file, frame range and rate, glTF key tolerance, size estimate, progress with Cancel).

#include <string>

#include "anim/take_export.h"
#include "sculpt/app_model.h"

namespace sculpt::app {

/// The bottom strip's recording row (inside the strip's window).
void drawRecordStrip(AppModel& model);
/// The export dialog, while model.exportDialog.show.
void drawExportDialog(AppModel& model);

/// The dialog's format at combo index `index`, and the name ending that asks for it.
ExportFormat exportFormatAt(int index);
const char* exportSuffix(int index);
/// The combo index of a format.
int exportFormatIndex(ExportFormat format);
/// The dialog's path field set to `path` (cut at the field's capacity).
void setExportPath(ExportDialog& dialog, const std::string& path);
/// `path` with its format's ending replaced by that of `index` ("a/x_take.glb" ->
/// "a/x_take_####.obj").
std::string withExportSuffix(const std::string& path, int index);

/// "1.2 MiB" and the like.
std::string byteSize(uint64_t bytes);

}  // namespace sculpt::app
