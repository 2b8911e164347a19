#pragma once
// A take's level-K solid as a ParaView time series: one unstructured grid per frame with the
// deformed nodes, the displacement (POINT_DATA) and the painted youngs_modulus, density and
// damping (CELL_DATA), plus collection files that give each frame its time (frame / fps):
//  - pattern name_####.vtk: legacy VTK 4.2 binary files, name.vtk.series (ParaView's file-series
//    JSON) and name.pvd;
//  - pattern name_####.vtu: VTK XML files (ASCII, 17 digits for doubles) and name.pvd.
// Collections name the frames relative to their own directory (the pattern's).

#include <filesystem>

#include "anim/animated_surface.h"
#include "anim/export_result.h"
#include "util/progress.h"

namespace sculpt {

/// Every file is written atomically; a cancelled or failed export removes the files it wrote.
/// Throws std::invalid_argument for a pattern without one run of '#' or with an extension other
/// than .vtk or .vtu, FileError when a file cannot be written.
ExportResult writeVtkSequence(const AnimatedSurface& animation,
                              const std::filesystem::path& pattern,
                              ProgressReporter* progress = nullptr);

}  // namespace sculpt
