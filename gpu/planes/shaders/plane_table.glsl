// The plane table the binning writes on the GPU (gpu/planes/shaders/plane_table_io.h: a
// PlaneTableHeader, then one PlaneTableEntry per plane and one past the last: d_k and the first
// sorted splat of plane k), read-only, for the passes that read it (the binning's own passes
// that write it declare it writable).
#include "gpu/planes/shaders/plane_table_io.h"

layout(std430, binding = kPlaneTableBinding) readonly buffer PlaneTable {
  PlaneTableHeader table;
  PlaneTableEntry plane[];
};
