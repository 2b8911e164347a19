#include "io/png_encoder.h"

#include <stdexcept>

#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#include <stb_image_write.h>

namespace sculpt {
namespace {

void append(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                             static_cast<size_t>(size));
}

}  // namespace

std::string encodePng(int width, int height, int channels, std::span<const uint8_t> pixels) {
  if (width <= 0 || height <= 0 || (channels != 3 && channels != 4) ||
      pixels.size() != static_cast<size_t>(width) * height * channels)
    throw std::runtime_error("encodePng: the pixel count does not match the image size");
  std::string png;
  if (!stbi_write_png_to_func(append, &png, width, height, channels, pixels.data(),
                              width * channels))
    throw std::runtime_error("encodePng: PNG encoding failed");
  return png;
}

}  // namespace sculpt
