// One triangle that covers the whole viewport (vertices from gl_VertexID, no buffers): the
// fragment shader addresses the pattern by window pixel, so no texture coordinates are needed.
// gpu::Program puts the #version line first.
void main() {
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
