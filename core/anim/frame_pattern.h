#pragma once
// File names of a frame sequence: a pattern such as out/name_####.obj names frame n (1-based)
// by replacing the one run of '#' in its file name with n, zero-padded to the run's length
// (name_0001.obj; numbers wider than the run are written in full, name_12345.obj). The
// collection files that list a sequence (ParaView's .pvd and .vtk.series) drop the run.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace sculpt {

struct FramePattern {
  std::filesystem::path directory;  ///< the pattern's parent path (may be empty)
  std::string prefix;               ///< file name before the '#' run
  std::string suffix;               ///< file name after it
  uint32_t width = 0;               ///< the run's length
};

/// The pattern when the file name holds exactly one run of '#'; nullopt otherwise ('#' in the
/// directory part does not count).
std::optional<FramePattern> parseFramePattern(const std::filesystem::path& pattern);

/// parseFramePattern, or std::invalid_argument with one sentence that shows how to write one.
FramePattern framePatternOrThrow(const std::filesystem::path& pattern);

bool isFramePattern(const std::filesystem::path& pattern);

/// The file of frame `frameNumber` (1-based).
std::filesystem::path framePath(const FramePattern& pattern, uint32_t frameNumber);

/// The pattern without the run and one '_', '-' or '.' before it, with `extension` (".pvd",
/// ".vtk.series") in place of its own: name_####.vtk -> name.pvd.
std::filesystem::path collectionPath(const FramePattern& pattern, std::string_view extension);

}  // namespace sculpt
