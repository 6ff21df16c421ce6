#version 450 core
// Shows an already tone-mapped sRGB8 frame.
in vec2 v_uv;
out vec4 color;
layout(binding = 0) uniform sampler2D frame;
void main() { color = vec4(texture(frame, v_uv).rgb, 1.0); }
