#version 330 core
// Flat colour; points are drawn as discs (gl_PointCoord is only defined for points, hence the
// uniform that says which primitive is being drawn).
in vec3 vertexColour;

uniform bool roundPoints;

out vec4 colour;

void main() {
  if (roundPoints && length(gl_PointCoord - vec2(0.5)) > 0.5) discard;
  colour = vec4(vertexColour, 1.0);
}
