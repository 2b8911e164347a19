// (render/ prepends "#version 330 core", lighting.glsl and colour_map.glsl)
// Shades the GPU-deformed surface: phong_deform.vert outputs view-space position and normal, and
// a field value that, when a field is shown, replaces the base colour through the colour map.
in vec3 viewPosition;
in vec3 viewNormal;
in float fieldValue;

uniform vec3 baseColour;
uniform int fieldMode;
uniform vec2 fieldRange;   // values mapped to the ends of the colour map
uniform bool flatShading;  // facet normals from screen-space derivatives
uniform vec4 solidColour;  // alpha > 0: unlit colour (wireframe overlay pass)

out vec4 colour;

void main() {
  if (solidColour.a > 0.0) {
    colour = solidColour;
    return;
  }
  vec3 normal = flatShading ? cross(dFdx(viewPosition), dFdy(viewPosition)) : viewNormal;
  vec3 base = baseColour;
  if (fieldMode != 0) {
    float span = max(fieldRange.y - fieldRange.x, 1e-30);
    base = pow(colourMap((fieldValue - fieldRange.x) / span), vec3(2.2));  // shade() re-encodes
  }
  colour = shade(viewPosition, normal, base);
}
