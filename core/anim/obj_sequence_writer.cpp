#include "anim/obj_sequence_writer.h"

#include <charconv>
#include <string>
#include <system_error>
#include <vector>

#include "anim/frame_pattern.h"
#include "io/atomic_file.h"
#include "io/file_error.h"
#include "io/number_text.h"

#include "anim/written_files.h"

namespace sculpt {
namespace {

// 9 significant digits (like "%.9g"): every float reads back bit for bit.
void appendFloat(std::string& out, float value) {
  char buffer[32];
  const auto result =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 9);
  out.append(buffer, result.ptr);
}

void appendFloats(std::string& out, std::string_view keyword, const float* values) {
  out += keyword;
  for (int k = 0; k < 3; ++k) {
    out += ' ';
    appendFloat(out, values[k]);
  }
  out += '\n';
}

std::string frameText(const AnimatedSurface& animation, uint32_t f, const SurfaceMesh& rest,
                      const SurfaceFrameData& frame, const std::filesystem::path& path) {
  const size_t vertices = rest.numVertices();
  const size_t normals = static_cast<size_t>(rest.normals.rows());
  if (frame.positions.size() != 3 * vertices) {
    throw FileError(path.string() + ": frame " + std::to_string(f + 1) + " has " +
                    std::to_string(frame.positions.size() / 3) + " positions but the surface has " +
                    std::to_string(vertices));
  }
  if (normals > 0 && frame.sourceNormals.size() != 3 * normals) {
    throw FileError(path.string() + ": frame " + std::to_string(f + 1) + " has " +
                    std::to_string(frame.sourceNormals.size() / 3) +
                    " normals but the surface has " + std::to_string(normals));
  }
  std::string out;
  out.reserve(40 * (vertices + normals) + 24 * rest.faces.values.size());
  out += "# frame ";
  appendNumber(out, f + 1);
  out += " of ";
  appendNumber(out, animation.frameCount());
  out += ", t = ";
  appendNumber(out, animation.frameTime(f));
  out += " s\n";
  for (size_t v = 0; v < vertices; ++v) appendFloats(out, "v", &frame.positions[3 * v]);
  for (Eigen::Index t = 0; t < rest.texcoords.rows(); ++t) {
    out += "vt ";
    appendNumber(out, rest.texcoords(t, 0));
    out += ' ';
    appendNumber(out, rest.texcoords(t, 1));
    out += '\n';
  }
  for (size_t n = 0; n < normals; ++n) appendFloats(out, "vn", &frame.sourceNormals[3 * n]);
  for (uint32_t face = 0; face < rest.numFaces(); ++face) {
    out += 'f';
    for (const SurfaceCorner& corner : rest.faces.row(face)) {
      out += ' ';
      appendNumber(out, corner.position + 1);
      const bool hasTexcoord = corner.texcoord != SurfaceCorner::kNoIndex;
      const bool hasNormal = corner.normal != SurfaceCorner::kNoIndex;
      if (hasTexcoord || hasNormal) out += '/';
      if (hasTexcoord) appendNumber(out, corner.texcoord + 1);
      if (hasNormal) {
        out += '/';
        appendNumber(out, corner.normal + 1);
      }
    }
    out += '\n';
  }
  return out;
}

}  // namespace

ExportResult writeObjSequence(const AnimatedSurface& animation,
                              const std::filesystem::path& pattern, ProgressReporter* progress) {
  const FramePattern names = framePatternOrThrow(pattern);
  const uint32_t frames = animation.frameCount();
  ExportResult result;
  WrittenFiles written;
  SurfaceFrameData frame;
  for (uint32_t f = 0; f < frames; ++f) {
    const std::filesystem::path path = framePath(names, f + 1);
    const SurfaceMesh& rest = animation.restSurface(animation.segmentOf(f));
    frame.withNormals = rest.normals.rows() > 0;  // only the source's own normals are written
    animation.evaluateSurface(f, frame);
    const std::string text = frameText(animation, f, rest, frame, path);
    writeFileAtomically(path, text);
    written.add(path);
    result.bytes += text.size();
    if (progress && !progress->report(double(f + 1) / frames, "OBJ sequence")) {
      ExportResult cancelled;
      cancelled.cancelled = true;
      return cancelled;  // `written` removes the frames
    }
  }
  result.files = written.keep();
  result.frames = frames;
  return result;
}

}  // namespace sculpt
