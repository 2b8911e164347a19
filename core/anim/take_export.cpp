#include "anim/take_export.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "anim/frame_pattern.h"
#include "anim/glb_animation_writer.h"
#include "anim/obj_sequence_writer.h"
#include "anim/point_cache_writer.h"
#include "anim/vtk_sequence_writer.h"
#include "util/file_extension.h"

namespace sculpt {
namespace {


}  // namespace

ExportTarget exportTargetFor(const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  ExportTarget target;
  if (ext == ".glb") target.format = ExportFormat::Glb;
  else if (ext == ".pc2") target.format = ExportFormat::Pc2;
  else if (ext == ".mdd") target.format = ExportFormat::Mdd;
  else if (ext == ".mp4") target.format = ExportFormat::Mp4;
  else if (ext == ".obj") target.format = ExportFormat::ObjSequence;
  else if (ext == ".vtk") target.format = ExportFormat::VtkSequence;
  else if (ext == ".vtu") target.format = ExportFormat::VtuSequence;
  else if (ext == ".png") target.format = ExportFormat::PngSequence;
  if (!target.format) {
    target.problem = path.string() + ": unknown kind of recording (expected .glb, .pc2, .mdd, "
                     "name_####.obj, name_####.vtk, name_####.vtu, name_####.png or .mp4)";
    return target;
  }
  const bool sequence = *target.format == ExportFormat::ObjSequence ||
                        *target.format == ExportFormat::VtkSequence ||
                        *target.format == ExportFormat::VtuSequence ||
                        *target.format == ExportFormat::PngSequence;
  if (sequence) {
    try {
      framePatternOrThrow(path);
    } catch (const std::invalid_argument& e) {
      target.format.reset();
      target.problem = e.what();
    }
  }
  return target;
}

const char* exportFormatName(ExportFormat format) {
  switch (format) {
    case ExportFormat::Glb: return "glTF binary (morph animation)";
    case ExportFormat::Pc2: return "PC2 point cache";
    case ExportFormat::Mdd: return "MDD point cache";
    case ExportFormat::ObjSequence: return "OBJ sequence";
    case ExportFormat::VtkSequence: return "VTK sequence";
    case ExportFormat::VtuSequence: return "VTU sequence";
    case ExportFormat::PngSequence: return "PNG frames";
    case ExportFormat::Mp4: return "MP4 video";
  }
  return "?";
}

bool isRenderedFormat(ExportFormat format) {
  return format == ExportFormat::PngSequence || format == ExportFormat::Mp4;
}

ExportResult exportAnimation(const AnimatedSurface& surface, const std::filesystem::path& path,
                             ExportFormat format, const TakeExportOptions& options,
                             ProgressReporter* progress) {
  switch (format) {
    case ExportFormat::Glb: {
      GlbAnimationOptions glb;
      glb.keyTolerance = options.keyTolerance;
      glb.name = path.stem().string();
      return writeGlbAnimation(surface, path, glb, progress);
    }
    case ExportFormat::Pc2: return writePc2(surface, path, progress);
    case ExportFormat::Mdd: return writeMdd(surface, path, progress);
    case ExportFormat::ObjSequence: return writeObjSequence(surface, path, progress);
    case ExportFormat::VtkSequence:
    case ExportFormat::VtuSequence: return writeVtkSequence(surface, path, progress);
    case ExportFormat::PngSequence:
    case ExportFormat::Mp4: break;
  }
  throw std::invalid_argument(std::string(exportFormatName(format)) +
                              " is rendered by the window program, not written here");
}

uint64_t estimateExportBytes(const AnimatedSurface& surface, ExportFormat format) {
  uint64_t vertices = 0, triangles = 0, nodes = 0, cells = 0;
  for (uint32_t s = 0; s < surface.segmentCount(); ++s) {
    vertices = std::max<uint64_t>(vertices, surface.restSurface(s).numVertices());
    triangles = std::max<uint64_t>(triangles, surface.triangles(s).size() / 3);
    nodes = std::max<uint64_t>(nodes, surface.restSolid(s).numNodes());
    cells = std::max<uint64_t>(cells, surface.restSolid(s).numCells());
  }
  const uint64_t frames = surface.frameCount();
  switch (format) {
    case ExportFormat::Glb:  // base + a key (positions, normals) every 4 frames
      return 12 * triangles + 24 * vertices * (1 + (frames + 3) / 4);
    case ExportFormat::Pc2:
    case ExportFormat::Mdd: return 32 + 12 * vertices * frames;
    case ExportFormat::ObjSequence: return frames * (40 * vertices + 30 * triangles);
    case ExportFormat::VtkSequence:
    case ExportFormat::VtuSequence: return frames * (48 * nodes + 48 * cells);
    case ExportFormat::PngSequence: return frames * 1'500'000;
    case ExportFormat::Mp4: return frames * 20'000;
  }
  return 0;
}

}  // namespace sculpt
