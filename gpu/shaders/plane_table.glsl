// The plane table the binning writes on the GPU (gpu/gl_planes.hpp: PlaneTableHeader, then one
// PlaneTableEntry per plane and one past the last: d_k and the first sorted splat of plane k).
// Prepended, read-only, to the shaders that read it (plane_table_source in gpu/gl_planes.hpp),
// after a line defining PLANE_TABLE_BINDING, its storage-buffer binding in that pass.
struct PlaneEntry {
  float depth;
  uint begin;
};
layout(std430, binding = PLANE_TABLE_BINDING) readonly buffer PlaneTable {
  uint plane_count;
  uint splats_binned;
  uint pad0, pad1;
  PlaneEntry plane[];
};
