#pragma once
// Exporting a take to the files named on the command line or in the window's export dialog:
// the output's name picks the format. Geometry formats are written here; images and video
// (.png sequences, .mp4) are rendered by the window program (app/sculpt), which this layer
// only recognises.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "anim/animated_surface.h"
#include "anim/export_result.h"
#include "util/progress.h"

namespace sculpt {

enum class ExportFormat {
  Glb,          ///< name.glb: morph-target animation
  Pc2,          ///< name.pc2: Blender point cache
  Mdd,          ///< name.mdd: LightWave point cache
  ObjSequence,  ///< name_####.obj
  VtkSequence,  ///< name_####.vtk (+ name.pvd, name.vtk.series)
  VtuSequence,  ///< name_####.vtu (+ name.pvd)
  PngSequence,  ///< name_####.png (rendered)
  Mp4,          ///< name.mp4 (rendered, H.264 through ffmpeg)
};

/// The format an output name asks for, or one sentence why it cannot be written (an unknown
/// extension, a sequence name without a #### run).
struct ExportTarget {
  std::optional<ExportFormat> format;
  std::string problem;
};
ExportTarget exportTargetFor(const std::filesystem::path& path);
const char* exportFormatName(ExportFormat format);
bool isRenderedFormat(ExportFormat format);

struct TakeExportOptions {
  double keyTolerance = 1e-3;  ///< glTF: relative to the rest bounding-box diagonal
};

/// Writes a geometry format (not a rendered one: std::invalid_argument). Throws FileError.
ExportResult exportAnimation(const AnimatedSurface& surface, const std::filesystem::path& path,
                             ExportFormat format, const TakeExportOptions& options,
                             ProgressReporter* progress = nullptr);

/// About how many bytes the export will write (glTF: assumes a key every 4 frames).
uint64_t estimateExportBytes(const AnimatedSurface& surface, ExportFormat format);

}  // namespace sculpt
