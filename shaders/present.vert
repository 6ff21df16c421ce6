#version 450 core
// Full-screen triangle for presenting a frame in a window.
out vec2 v_uv;
void main() {
  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  v_uv = vec2(p.x, 1.0 - p.y);  // frame rows start at the top
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
