// The throughput probe's raster fill (gpu/probes/gl_throughput_probe.hpp): one triangle covering the
// whole target per instance (the vertex id picks a corner), drawn many times over.
void main() {
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
