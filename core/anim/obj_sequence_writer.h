#pragma once
// A take as one Wavefront OBJ per frame (pattern name_####.obj, frame 1 first): each file is
// the rest surface as its file had it (vertex order, texture coordinates, normals, faces with
// the same v, v/vt, v//vn or v/vt/vn corners) with the frame's positions and normals. Positions
// and normals are printed with 9 significant digits, so they read back as the same float32.

#include <filesystem>

#include "anim/animated_surface.h"
#include "anim/export_result.h"
#include "util/progress.h"

namespace sculpt {

/// Writes frame f to framePath(pattern, f + 1), each file atomically. A cancelled or failed
/// export removes the frames it wrote. Throws std::invalid_argument for a pattern without one
/// run of '#' (frame_pattern.h) and FileError when a file cannot be written.
ExportResult writeObjSequence(const AnimatedSurface& animation,
                              const std::filesystem::path& pattern,
                              ProgressReporter* progress = nullptr);

}  // namespace sculpt
