#pragma once
// PNG encoding of 8-bit images (charts, screenshots). One stb_image_write instance for the whole
// program, kept private to its .cpp (Debian's tinygltf library exports the same symbols).

#include <cstdint>
#include <span>
#include <string>

namespace sculpt {

/// PNG bytes of a top-row-first image with `channels` (3 = RGB, 4 = RGBA) bytes per pixel.
/// Throws std::runtime_error when the size does not match or encoding fails.
std::string encodePng(int width, int height, int channels, std::span<const uint8_t> pixels);

}  // namespace sculpt
