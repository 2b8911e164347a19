#include "render/image_downsample.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace sculpt::render {

std::vector<uint8_t> downsample(std::span<const uint8_t> rgba, int width, int height, int factor) {
  if (factor < 1 || width < factor || height < factor || width % factor || height % factor ||
      rgba.size() != 4 * static_cast<size_t>(width) * static_cast<size_t>(height))
    throw std::invalid_argument("downsample: a " + std::to_string(width) + "x" +
                                std::to_string(height) + " image cannot be reduced by " +
                                std::to_string(factor));
  const int w = width / factor, h = height / factor;
  std::vector<uint8_t> out(4 * static_cast<size_t>(w) * static_cast<size_t>(h));
  const double samples = static_cast<double>(factor) * factor;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double colour[3] = {0, 0, 0}, alpha = 0;
      for (int sy = 0; sy < factor; ++sy)
        for (int sx = 0; sx < factor; ++sx) {
          const uint8_t* p =
              rgba.data() + 4 * (static_cast<size_t>(y * factor + sy) * static_cast<size_t>(width) +
                                 static_cast<size_t>(x * factor + sx));
          const double a = p[3];
          for (int c = 0; c < 3; ++c) colour[c] += a * p[c];
          alpha += a;
        }
      uint8_t* q = out.data() +
                   4 * (static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x));
      for (int c = 0; c < 3; ++c)
        q[c] = alpha > 0 ? static_cast<uint8_t>(std::lround(colour[c] / alpha)) : 0;
      q[3] = static_cast<uint8_t>(std::lround(alpha / samples));
    }
  return out;
}

}  // namespace sculpt::render
