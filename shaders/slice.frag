// (render/ prepends "#version 330 core" and colour_map.glsl)
// The field through the colour map, unlit: the section is flat, and lighting would only shift
// the colours away from the legend's.
in float fieldValue;

uniform float low;
uniform float high;

out vec4 colour;

void main() {
  float range = high - low;
  float t = range > 0.0 ? (fieldValue - low) / range : 0.5;
  colour = vec4(colourMap(t), 1.0);
}
