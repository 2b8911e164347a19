// Supersampled screenshots are averaged down with an alpha-weighted box filter.

#include <gtest/gtest.h>

#include <stdexcept>

#include "render/image_downsample.h"

namespace sculpt::render {
namespace {

TEST(ImageDownsample, AveragesOpaqueBlocks) {
  // 4x2 image, factor 2: left block black/white checker -> grey 128 (rounded), right block red.
  std::vector<uint8_t> image = {0,   0,   0,   255, 255, 255, 255, 255, 255, 0,  0,
                                255, 255, 0,   0,   255, 255, 255, 255, 255, 0,  0,
                                0,   255, 255, 0,   0,   255, 255, 0,   0,   255};
  const std::vector<uint8_t> out = downsample(image, 4, 2, 2);
  ASSERT_EQ(out.size(), 8u);
  EXPECT_EQ(out[0], 128);
  EXPECT_EQ(out[1], 128);
  EXPECT_EQ(out[3], 255);
  EXPECT_EQ(out[4], 255);
  EXPECT_EQ(out[5], 0);
  EXPECT_EQ(out[7], 255);
}

TEST(ImageDownsample, TransparentBackgroundDoesNotDarkenTheEdge) {
  // One opaque orange pixel among three transparent black ones: colour stays orange, alpha 1/4.
  std::vector<uint8_t> image = {200, 100, 50, 255, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  const std::vector<uint8_t> out = downsample(image, 2, 2, 2);
  EXPECT_EQ(out[0], 200);
  EXPECT_EQ(out[1], 100);
  EXPECT_EQ(out[2], 50);
  EXPECT_EQ(out[3], 64);  // 255 / 4 rounded
}

TEST(ImageDownsample, FactorOneIsIdentityAndBadSizesThrow) {
  std::vector<uint8_t> image(4 * 3 * 2);
  for (size_t i = 0; i < image.size(); ++i) image[i] = static_cast<uint8_t>(i * 7);
  for (size_t i = 3; i < image.size(); i += 4) image[i] = 255;
  EXPECT_EQ(downsample(image, 3, 2, 1), image);
  EXPECT_THROW(downsample(image, 3, 2, 2), std::invalid_argument);
  EXPECT_THROW(downsample(image, 4, 2, 2), std::invalid_argument);  // wrong byte count
}

}  // namespace
}  // namespace sculpt::render
