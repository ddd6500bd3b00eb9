// One triangle that covers the whole viewport (the conversion runs once per quilt pixel).
out vec2 v_uv;
void main() {
  const vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  v_uv = corner;
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
