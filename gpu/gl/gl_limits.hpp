#pragma once
// The limits of the current context that lfd's passes size themselves by (docs/gpu.md "Drivers
// and limits"): read from the context, never assumed, in one place. Every pass that splits work to
// fit (the tile rasterizers' passes, the voxel atlas, the interlacer's textures, the scene
// buffers) reads them here; every compute program's work group is checked against them at link
// (gpu::Program). LFD_GL_LIMITS lowers them, so a test can run llvmpipe as a smaller device
// (NVIDIA's 48 KiB of shared memory, a 128 MiB storage block, 16384 texels) and check that the
// images do not change: "storage=134217728,shared=49152,invocations=1024,texture=16384,layers=2048"
// (any subset; a value above the context's own limit leaves it as it is).
#include <string_view>

namespace lfd::gpu {

struct GlLimits {
  long long storage_block_bytes = 0;  // GL_MAX_SHADER_STORAGE_BLOCK_SIZE: the largest buffer a pass binds
  int shared_bytes = 0;               // GL_MAX_COMPUTE_SHARED_MEMORY_SIZE (the spec's floor is 32 KiB)
  int invocations = 0;                // GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS (floor 1024)
  int work_groups_x = 0;              // GL_MAX_COMPUTE_WORK_GROUP_COUNT[0] (floor 65535)
  int texture_size = 0;               // GL_MAX_TEXTURE_SIZE (floor 16384 in GL 4.5)
  int array_layers = 0;               // GL_MAX_ARRAY_TEXTURE_LAYERS (floor 2048)
};

// The current context's limits, lowered by LFD_GL_LIMITS. A malformed LFD_GL_LIMITS is an
// InputError naming the field.
GlLimits gl_limits();

// The limits `queried` lowered by an LFD_GL_LIMITS value `lowered` (what gl_limits applies).
GlLimits lower_gl_limits(GlLimits queried, std::string_view lowered);

}  // namespace lfd::gpu
