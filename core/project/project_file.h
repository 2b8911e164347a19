#pragma once
// The project file (`.sculpt`, docs/file-formats.md "Project files"):
//   "SCULPT\0" | format version (uint32 LE) | manifest length (uint32 LE) | manifest CRC-32 |
//   manifest (JSON, keys sorted) | blobs (little-endian arrays, in manifest order, each CRC-32'd)
// The same project always gives the same bytes (no timestamps, sorted maps), so save -> load ->
// save is byte-identical and undo can be checked by comparing saves.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "io/file_error.h"
#include "project/project.h"

namespace sculpt {

inline constexpr char kProjectExtension[] = ".sculpt";
inline constexpr uint32_t kProjectFormatVersion = 1;

/// The file's bytes. Throws std::invalid_argument (one sentence) for a project that could not be
/// read back: non-finite numbers, out-of-range vertex ids, mismatched sample arrays.
std::string serializeProject(const Project& project);
/// Parses bytes produced by serializeProject. Never reads past `bytes`; throws FileError with one
/// sentence prefixed by `sourceName` (truncated, bad magic, newer version, checksum mismatch,
/// inconsistent counts, bad JSON, non-finite numbers, out-of-range ids).
Project parseProject(std::string_view bytes, std::string_view sourceName);

/// Writes atomically (temporary file, flush, rename): a failed or killed save leaves the previous
/// file as it was. Throws std::invalid_argument (see serializeProject) or FileError.
void saveProject(const Project& project, const std::filesystem::path& path);
/// Reads and parses. Throws FileError.
Project loadProject(const std::filesystem::path& path);

}  // namespace sculpt
