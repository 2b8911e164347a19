#version 330 core
// A surface from a static vertex buffer (render/surface_renderer: the benchmark's reference draw):
// position and normal per vertex, transformed to view space for lighting.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

uniform mat4 modelView;
uniform mat4 projection;

out vec3 viewPosition;
out vec3 viewNormal;

void main() {
  vec4 p = modelView * vec4(position, 1.0);
  viewPosition = p.xyz;
  viewNormal = mat3(modelView) * normal;
  gl_Position = projection * p;
}
