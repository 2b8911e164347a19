#include "anim/point_cache_writer.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <bit>
#include <cerrno>
#include <cstdint>
#include <string>
#include <string_view>
#include <system_error>

#include "anim/stream_file.h"
#include "io/file_error.h"

namespace sculpt {
namespace {

enum class CacheFormat { kPc2, kMdd };


void appendLittleEndian(std::string& out, uint32_t bits) {
  for (int i = 0; i < 4; ++i) out += static_cast<char>((bits >> (8 * i)) & 0xffu);
}

void appendBigEndian32(std::string& out, uint32_t bits) {
  for (int i = 3; i >= 0; --i) out += static_cast<char>((bits >> (8 * i)) & 0xffu);
}

void appendWord(std::string& out, uint32_t bits, CacheFormat format) {
  if (format == CacheFormat::kPc2) {
    appendLittleEndian(out, bits);
  } else {
    appendBigEndian32(out, bits);
  }
}

void appendFloat(std::string& out, float value, CacheFormat format) {
  appendWord(out, std::bit_cast<uint32_t>(value), format);
}

// The one vertex count of the take; throws when a later segment has another.
uint32_t vertexCount(const AnimatedSurface& animation, const std::filesystem::path& path) {
  const uint32_t count = animation.restSurface(0).numVertices();
  for (uint32_t s = 1; s < animation.segmentCount(); ++s) {
    const FrameRange range = animation.segment(s);
    if (range.count == 0 || animation.restSurface(s).numVertices() == count) continue;
    throw FileError(path.string() +
                    ": a point cache needs one vertex count; the take changes topology at "
                    "frame " +
                    std::to_string(range.first + 1) + " (use .glb or a sequence)");
  }
  return count;
}

ExportResult writePointCache(const AnimatedSurface& animation, const std::filesystem::path& path,
                             ProgressReporter* progress, CacheFormat format) {
  const uint32_t frames = animation.frameCount();
  if (frames == 0 || animation.segmentCount() == 0) {
    throw FileError(path.string() + ": the take has no frames to write");
  }
  const uint32_t vertices = vertexCount(animation, path);

  StreamFile file(path);
  std::string bytes;
  if (format == CacheFormat::kPc2) {
    bytes.append("POINTCACHE2", 12);  // with its terminating zero
    appendWord(bytes, 1, format);
    appendWord(bytes, vertices, format);
    appendFloat(bytes, 1.0f, format);
    appendFloat(bytes, 1.0f, format);
    appendWord(bytes, frames, format);
  } else {
    appendWord(bytes, frames, format);
    appendWord(bytes, vertices, format);
    for (uint32_t f = 0; f < frames; ++f) {
      appendFloat(bytes, static_cast<float>(animation.frameTime(f)), format);
    }
  }
  file.write(bytes.data(), bytes.size());

  ExportResult result;
  SurfaceFrameData frame;
  frame.withNormals = false;  // a point cache holds positions only
  for (uint32_t f = 0; f < frames; ++f) {
    animation.evaluateSurface(f, frame);
    if (frame.positions.size() != 3 * size_t{vertices}) {
      throw FileError(path.string() + ": frame " + std::to_string(f + 1) + " has " +
                      std::to_string(frame.positions.size() / 3) + " vertices instead of " +
                      std::to_string(vertices));
    }
    bytes.clear();
    for (const float value : frame.positions) appendFloat(bytes, value, format);
    file.write(bytes.data(), bytes.size());
    if (progress && !progress->report(double(f + 1) / frames, "point cache")) {
      result.cancelled = true;
      return result;  // the partial file goes with `file`
    }
  }
  file.commit();
  result.files.push_back(path);
  result.bytes = file.written();
  result.frames = frames;
  return result;
}

}  // namespace

ExportResult writePc2(const AnimatedSurface& animation, const std::filesystem::path& path,
                      ProgressReporter* progress) {
  return writePointCache(animation, path, progress, CacheFormat::kPc2);
}

ExportResult writeMdd(const AnimatedSurface& animation, const std::filesystem::path& path,
                      ProgressReporter* progress) {
  return writePointCache(animation, path, progress, CacheFormat::kMdd);
}

}  // namespace sculpt
