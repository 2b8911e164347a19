#pragma once
// A take as a glTF 2.0 binary (.glb) morph-target animation: one mesh per segment whose morph
// targets are key frames (anim/morph_keys.h), cross-faded by a linear weights animation so that
// between two keys the surface is their linear interpolation. Segments (one topology each) are
// separate nodes, each shown only during its frames by a stepped scale animation.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "anim/animated_surface.h"
#include "anim/export_result.h"
#include "anim/morph_keys.h"
#include "util/progress.h"

namespace sculpt {

struct GlbAnimationOptions {
  /// Key tolerance relative to the rest surface's bounding-box diagonal (morphKeyTolerance()).
  double keyTolerance = 1e-3;
  uint32_t maxKeySpan = 32;   ///< the most frames from one key to the next
  std::string name = "take";  ///< names the animation, nodes, meshes and shape keys
};

/// Writes the take to `path` (temporary file, renamed at the end). Reports the fraction of the
/// work done; when cancelled returns with `cancelled` set and no file written. Throws FileError
/// with one sentence naming the file, before writing anything when the file would exceed the
/// format's 4 GiB limit. `keys`, when given, receives each segment's keys.
ExportResult writeGlbAnimation(const AnimatedSurface& take, const std::filesystem::path& path,
                               const GlbAnimationOptions& options, ProgressReporter* progress,
                               std::vector<MorphKeys>* keys = nullptr);

/// What one segment stores, for the file's size.
struct GlbSegmentLayout {
  uint64_t vertices = 0;
  uint64_t triangles = 0;
  uint64_t keys = 0;
  bool normals = false;
  bool texcoords = false;
  bool scaleChannel = false;  ///< several segments: a visibility channel of `scaleKeys` keys
  uint64_t scaleKeys = 0;
};

/// Bytes of the binary chunk's data for these segments.
uint64_t glbBinaryBytes(const std::vector<GlbSegmentLayout>& segments);

/// The largest total length a .glb can declare (its header's 32-bit length).
inline constexpr uint64_t kGlbMaxBytes = 0xffffffffull;

/// Throws FileError "path: N keys of M vertices need X GiB, over glTF binary's 4 GiB limit; ..."
/// when `totalBytes` exceeds kGlbMaxBytes; M is the largest segment's vertex count.
void checkGlbSize(const std::filesystem::path& path, uint64_t totalBytes,
                  const std::vector<GlbSegmentLayout>& segments);

}  // namespace sculpt
