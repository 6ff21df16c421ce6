#version 450 core
// Shows an already tone-mapped sRGB8 frame.
in vec2 v_uv;
out vec4 color;
layout(binding = TEX_PRESENT_FRAME) uniform sampler2D presented;
void main() { color = vec4(texture(presented, v_uv).rgb, 1.0); }
