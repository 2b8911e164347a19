#pragma once
// RGBA8 images to PNG files (screenshots).

#include <cstdint>
#include <filesystem>
#include <span>

namespace sculpt::render {

/// Writes top-row-first RGBA8 pixels as a PNG, atomically. Throws std::runtime_error (FileError on
/// I/O).
void writePng(const std::filesystem::path& path, int width, int height,
              std::span<const uint8_t> rgba);

}  // namespace sculpt::render
