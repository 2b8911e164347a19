#version 330 core
// Draws the surface that phong_deform.vert deformed into a buffer (transform feedback): world
// position, normal and field value per vertex, to view space for lighting, clipped by one plane.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in float field;

uniform mat4 modelView;
uniform mat4 projection;
uniform vec4 clipPlane;  // kept where dot(xyz, position) <= w

out vec3 viewPosition;
out vec3 viewNormal;
out float fieldValue;

void main() {
  vec4 p = modelView * vec4(position, 1.0);
  viewPosition = p.xyz;
  viewNormal = mat3(modelView) * normal;
  fieldValue = field;
  gl_ClipDistance[0] = clipPlane.w - dot(clipPlane.xyz, position);
  gl_Position = projection * p;
}
