#include "render/png_image.h"

#include <stdexcept>
#include <string>

#include "io/atomic_file.h"

// stb's writer compiled privately into this file (the tinygltf library carries its own copy).
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#include <stb_image_write.h>

namespace sculpt::render {
namespace {

void append(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                             static_cast<size_t>(size));
}

}  // namespace

void writePng(const std::filesystem::path& path, int width, int height,
              std::span<const uint8_t> rgba) {
  if (rgba.size() != static_cast<size_t>(width) * height * 4)
    throw std::runtime_error("writePng: pixel count does not match the size");
  std::string bytes;
  if (!stbi_write_png_to_func(append, &bytes, width, height, 4, rgba.data(), width * 4))
    throw std::runtime_error("cannot encode " + path.string());
  writeFileAtomically(path, bytes);
}

}  // namespace sculpt::render
