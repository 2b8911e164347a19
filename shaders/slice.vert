#version 330 core
// The clipping-plane section of the solid: a position and a field value per vertex.
layout(location = 0) in vec3 position;
layout(location = 1) in float value;

uniform mat4 view;
uniform mat4 projection;

out float fieldValue;

void main() {
  fieldValue = value;
  gl_Position = projection * (view * vec4(position, 1.0));
}
