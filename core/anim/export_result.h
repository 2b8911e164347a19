#pragma once
// What an animation writer reports. Every writer takes a ProgressReporter (util/progress.h):
// it reports the fraction of frames written and stops when the reporter cancels. A cancelled or
// failed export leaves nothing under the final names: single files are written to a temporary
// name and renamed at the end; a sequence removes the frames it wrote. Failures throw FileError
// (io/file_error.h) with one sentence naming the file.

#include <cstdint>
#include <filesystem>
#include <vector>

namespace sculpt {

struct ExportResult {
  std::vector<std::filesystem::path> files;  ///< written, in order (empty when cancelled)
  uint64_t bytes = 0;                        ///< their total size
  uint32_t frames = 0;                       ///< frames written
  uint32_t keys = 0;                         ///< glTF: morph targets (key frames); else 0
  bool cancelled = false;
};

}  // namespace sculpt
