#pragma once
// The colour map of scalar fields (viridis) on the CPU, for legends and colour bars. The GPU copy
// is shaders/colour_map.glsl (kColourMapGlsl), with the same coefficients.

#include <glm/glm.hpp>

namespace sculpt::render {

/// Linear RGB in [0,1] for t in [0,1] (t is clamped; NaN maps to the low end). Values are meant
/// to be written to an RGBA8 target as they are, without an sRGB conversion.
glm::vec3 colourMap(float t);

}  // namespace sculpt::render
