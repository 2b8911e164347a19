#pragma once
// Supersampled screenshots: an image rendered `factor` times larger, averaged back down.

#include <cstdint>
#include <span>
#include <vector>

namespace sculpt::render {

/// Box-filters RGBA8 pixels (width x height, rows in any order) by `factor` in each direction.
/// Colours are averaged weighted by alpha, so that a transparent background does not darken the
/// silhouette; alpha is averaged plainly. width and height must be multiples of factor
/// (std::invalid_argument otherwise).
std::vector<uint8_t> downsample(std::span<const uint8_t> rgba, int width, int height, int factor);

}  // namespace sculpt::render
