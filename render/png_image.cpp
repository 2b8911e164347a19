#include "render/png_image.h"


#include "io/atomic_file.h"
#include "io/png_encoder.h"

namespace sculpt::render {

void writePng(const std::filesystem::path& path, int width, int height,
              std::span<const uint8_t> rgba) {
  writeFileAtomically(path, encodePng(width, height, 4, rgba));
}

}  // namespace sculpt::render
