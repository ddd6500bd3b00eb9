// G2LF depth binning, pass 4: the plane (array layer) of every binned splat in sorted order, for
// the layered raster's gl_Layer: the last plane whose first splat is not after it.
layout(local_size_x = 256) in;

struct PlaneEntry {
  float depth;
  uint begin;
};
layout(std430, binding = 8) writeonly buffer Layers { uint layers[]; };
layout(std430, binding = 9) readonly buffer PlaneTable {
  uint plane_count;
  uint splats_binned;
  uint pad0, pad1;
  PlaneEntry plane[];
};

void main() {
  const uint i = gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x;
  if (i >= splats_binned) return;
  uint lo = 0u, hi = plane_count;  // planes with begin <= i: [0, lo)
  while (lo < hi) {
    const uint mid = (lo + hi) / 2u;
    if (plane[mid].begin <= i) lo = mid + 1u;
    else hi = mid;
  }
  layers[i] = lo - 1u;
}
