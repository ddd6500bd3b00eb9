// The sweeping-plane frame's contract (G2LF and V2LF on GL: gpu/planes/gl_sweeping_planes.hpp and the
// passes it runs): the storage-buffer binding points of the scene, the splat preprocess, the
// depth binning, the plane raster and the voxel passes, which share one set of binding points
// (each pass declares what it reads and writes there and binds it itself: docs/gpu.md "Binding
// points"), the binning's limits and every pass's work-group size. The plane table is gpu/planes/shaders/plane_table_io.h; the plane images'
// units gpu/planes/shaders/plane_io.h. Read by C++ and GLSL (gpu/gl/shaders/shader_io.h).
#ifndef LFD_GPU_SHADERS_FRAME_IO_H
#define LFD_GPU_SHADERS_FRAME_IO_H
#include "gpu/planes/shaders/plane_table_io.h"
#include "gpu/gl/shaders/shader_io.h"

LFD_IO_BEGIN(gpu)

// The Gaussian scene (gpu/splats/gl_scene.hpp): vec4s per Gaussian.
LFD_IO_INT(kScenePositionsBinding, 0)  // xyz, opacity
LFD_IO_INT(kSceneScalesBinding, 1)
LFD_IO_INT(kSceneRotationsBinding, 2)  // w, x, y, z
LFD_IO_INT(kSceneShBinding, 3)  // SH, shared with the voxel scene (gpu/splats/shaders/sh_color.glsl)

// The voxel scene (gpu/voxels/gl_voxel_scene.hpp), in the scene's points (a frame draws one scene).
LFD_IO_INT(kVoxelBoxesBinding, 0)      // min xyz, edge
LFD_IO_INT(kVoxelDensitiesBinding, 1)  // corners 0-3, 4-7
LFD_IO_INT(kVoxelOrderBinding, 2)      // eight octant orders (gpu/voxels/gl_voxel_raster.hpp)

// The splat passes and the sort between them (gpu/splats/gl_splat_preprocess.hpp).
LFD_IO_INT(kSplatRecordsBinding, 4)     // SplatRecord (gpu/splats/shaders/splat_record_io.h)
LFD_IO_INT(kSplatKeysBinding, 5)        // sort keys
LFD_IO_INT(kSplatValuesBinding, 6)      // sorted: the primitive index of each sorted position
LFD_IO_INT(kSplatDrawBinding, 7)        // the raster's indirect draw
LFD_IO_INT(kSplatLayersBinding, 8)      // layered raster: the plane of each sorted position
LFD_IO_INT(kSplatDepthRangeBinding, 11)  // the visible depths' range (the sort's normalised keys)
LFD_IO_INT(kSplatAccumulationUnit, 0)   // texture unit: the composite pass reads the accumulation

// The depth binning (gpu/splats/gl_depth_binning.hpp; the plane table at kPlaneTableBinding, 9).
LFD_IO_INT(kBinningCutsBinding, 10)
// N_chunk, the most chunks (planes) one binning makes; the chunk pass merges its K + 1 count
// cuts and M - 1 disparity cuts (K + M = N_chunk, M <= N_chunk / 2) in shared memory.
LFD_IO_UINT(kBinningMaxChunks, 4096u)
LFD_IO_UINT(kBinningMaxCuts, kBinningMaxChunks + 1u)
LFD_IO_UINT(kBinningMaxDisparityChunks, kBinningMaxChunks / 2u)

// The plane raster's batches (gpu/splats/gl_plane_raster.hpp).
LFD_IO_INT(kPlaneBatchesBinding, 11)     // PlaneBatch per batch
LFD_IO_INT(kPlaneBatchDrawBinding, 12)   // the batch's indirect draw
LFD_IO_INT(kPlaneBatchIdsBinding, 13)    // the batch's splats
LFD_IO_INT(kPlaneBatchLayersBinding, 14) // and their layers within the batch
// A batch of planes' sorted splat run and the copy pass's indirect dispatch (std430, 32 bytes).
struct PlaneBatch {
  uint groups_x LFD_IO_ZERO;  // DispatchIndirectCommand of the copy pass
  uint groups_y LFD_IO_ZERO;
  uint groups_z LFD_IO_ZERO;
  uint first LFD_IO_ZERO;  // first sorted splat of the batch
  uint count LFD_IO_ZERO;  // its splats
  uint pad0 LFD_IO_ZERO;
  uint pad1 LFD_IO_ZERO;
  uint pad2 LFD_IO_ZERO;
};

// The voxel binning and raster (gpu/voxels/gl_voxel_binning.hpp, gpu/voxels/gl_voxel_raster.hpp).
LFD_IO_INT(kVoxelDrawsBinding, 4)    // per plane 8 indirect draws (one per octant), then the dispatches
LFD_IO_INT(kVoxelChunkOfBinding, 11) // the chunk of each voxel
LFD_IO_UINT(kVoxelOctants, 8u)  // draws per plane: command kVoxelOctants k + octant, uvec4 each

// Work-group sizes (local_size_x; the C++ side dispatches ceil(n / size) groups).
LFD_IO_UINT(kSplatPreprocessGroupSize, 128u)
LFD_IO_UINT(kBinningKeysGroupSize, 256u)
LFD_IO_UINT(kBinningCutsGroupSize, 64u)
LFD_IO_UINT(kBinningChunksGroupSize, 256u)  // one work group merges every cut
LFD_IO_UINT(kBinningLayersGroupSize, 256u)
LFD_IO_UINT(kPlaneBatchesGroupSize, 64u)
LFD_IO_UINT(kPlaneCopyGroupSize, 256u)
LFD_IO_UINT(kVoxelBinningGroupSize, 256u)  // keys, chunk of, orders
LFD_IO_UINT(kVoxelDrawsGroupSize, 64u)

LFD_IO_END

#endif
