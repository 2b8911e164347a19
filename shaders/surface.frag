// (render/ prepends "#version 330 core" and lighting.glsl)
in vec3 viewPosition;
in vec3 viewNormal;

uniform vec3 baseColour;

out vec4 colour;

void main() { colour = shade(viewPosition, viewNormal, baseColour); }
