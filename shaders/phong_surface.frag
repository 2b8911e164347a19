// (render/ prepends "#version 330 core" and lighting.glsl)
// Shades the GPU-deformed surface: phong_deform.vert outputs world-space position and normal.
in vec3 deformedPosition;
in vec3 deformedNormal;

uniform mat4 modelView;
uniform vec3 baseColour;

out vec4 colour;

void main() {
  vec3 viewPosition = (modelView * vec4(deformedPosition, 1.0)).xyz;
  colour = shade(viewPosition, mat3(modelView) * deformedNormal, baseColour);
}
