#pragma once
// Point caches: the surface's vertex positions per frame, for a program that already has the
// mesh (Blender's Mesh Cache modifier, 3ds Max, LightWave, Houdini). Only positions are stored,
// in the rest surface's vertex order, as the float32 values evaluateSurface() gives, so the
// take must keep one vertex count throughout.
//
//  - PC2 (little-endian): "POINTCACHE2\0", int32 version 1, int32 vertices, float32 start frame
//    1 (a scene's first frame), float32 sampling 1 (one sample per frame), int32 frames, then
//    x y z per vertex per frame.
//  - MDD (big-endian): int32 frames, int32 vertices, float32 time in seconds per frame, then
//    x y z per vertex per frame.
//
// Blender's Mesh Cache modifier (frame time mode) ignores the PC2 start: cache frame i shows at
// scene frame i + the modifier's Frame Start, so Frame Start 1 puts the take's first frame on
// scene frame 1 for both formats.
//
// Frames are streamed to a temporary file beside the target and renamed at the end (see
// export_result.h for cancellation and errors).

#include <filesystem>

#include "anim/animated_surface.h"
#include "anim/export_result.h"
#include "util/progress.h"

namespace sculpt {

/// Throws FileError when the file cannot be written or the take changes its vertex count.
ExportResult writePc2(const AnimatedSurface& animation, const std::filesystem::path& path,
                      ProgressReporter* progress = nullptr);

/// As writePc2, in the MDD format.
ExportResult writeMdd(const AnimatedSurface& animation, const std::filesystem::path& path,
                      ProgressReporter* progress = nullptr);

}  // namespace sculpt
