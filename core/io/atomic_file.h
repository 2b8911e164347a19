#pragma once
// Whole-file reads and crash-safe writes. A writer never leaves a half-written file behind: the
// contents go to a temporary file in the same directory, are flushed to disk, and only then
// replace the destination with one rename.

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace sculpt {

/// Writes `contents` to `path` atomically (temporary file, write, fsync, rename). On failure the
/// temporary file is removed and the destination is left as it was. Throws FileError.
void writeFileAtomically(const std::filesystem::path& path, std::string_view contents);

/// Removes the temporary files that writers of `path` left beside it when they were killed
/// mid-write (SIGKILL, power loss: nothing ran to remove them). A temporary of a process that
/// still runs is kept: it may be writing now. Returns how many were removed; never throws.
size_t removeStaleTemporaries(const std::filesystem::path& path);

/// Reads the whole file as bytes. Throws FileError ("<path>: cannot open (<reason>)").
std::string readFile(const std::filesystem::path& path);

}  // namespace sculpt
