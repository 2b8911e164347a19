#version 330 core
// Overlay lines and points (grid, axes, cell edges, control mesh): a position and a colour per
// vertex, no lighting.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 colour;

uniform mat4 view;
uniform mat4 projection;
uniform float pointSize;

out vec3 vertexColour;

void main() {
  vertexColour = colour;
  gl_PointSize = pointSize;
  gl_Position = projection * (view * vec4(position, 1.0));
}
