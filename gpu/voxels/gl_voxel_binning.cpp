#include "gpu/voxels/gl_voxel_binning.hpp"

#include <bit>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "gpu/splats/gl_splat_preprocess.hpp"
#include "gpu/splats/shaders/frame_io.h"
#include "gpu/voxels/shaders/voxel_binning_chunk_of.comp.glsl.hpp"
#include "gpu/voxels/shaders/voxel_binning_draws.comp.glsl.hpp"
#include "gpu/voxels/shaders/voxel_binning_keys.comp.glsl.hpp"
#include "gpu/voxels/shaders/voxel_binning_orders.comp.glsl.hpp"

namespace lfd::gpu {
namespace {

Program keys_program() {
  return Program("v2lf binning: keys", {{GL_COMPUTE_SHADER, voxel_binning_keys_comp_glsl}}, {"SIGNED_DEPTH_KEYS 1"},
                 {storage_buffer("boxes", kVoxelBoxesBinding, Access::read),
                  storage_buffer("keys", kSplatKeysBinding, Access::write),
                  storage_buffer("values", kSplatValuesBinding, Access::write),
                  storage_buffer("plane_table", kPlaneTableBinding, Access::read_write)});
}

}  // namespace

GlVoxelBinning::GlVoxelBinning()
    : keys_(keys_program()),
      chunk_of_("v2lf binning: chunk of", {{GL_COMPUTE_SHADER, voxel_binning_chunk_of_comp_glsl}}, {},
                {storage_buffer("values", kSplatValuesBinding, Access::read),
                 storage_buffer("layers", kSplatLayersBinding, Access::read),
                 storage_buffer("plane_table", kPlaneTableBinding, Access::read),
                 storage_buffer("chunk_of", kVoxelChunkOfBinding, Access::write)}),
      orders_("v2lf binning: orders", {{GL_COMPUTE_SHADER, voxel_binning_orders_comp_glsl}}, {},
              {storage_buffer("order", kVoxelOrderBinding, Access::read),
               storage_buffer("keys", kSplatKeysBinding, Access::write),
               storage_buffer("values", kSplatValuesBinding, Access::write),
               storage_buffer("chunk_of", kVoxelChunkOfBinding, Access::read)}),
      draws_pass_("v2lf binning: draws", {{GL_COMPUTE_SHADER, voxel_binning_draws_comp_glsl}}, {},
                  {storage_buffer("plane_table", kPlaneTableBinding, Access::read),
                   storage_buffer("draws", kVoxelDrawsBinding, Access::write)}),
      chunking_(DepthKeys::kSigned) {}

size_t GlVoxelBinning::bytes() const {
  return keys_buffer_.bytes() + values_.bytes() + layers_.bytes() + chunk_of_buffer_.bytes() + group_keys_.bytes() +
         group_sorted_.bytes() + group_values_.bytes() + draws_.bytes() + sort_.scratch_bytes();
}

void GlVoxelBinning::keys(const GlVoxelScene& scene, const render::Camera& camera, GlPlaneTable& table) {
  const size_t n = scene.size();
  // The header counts binned voxels with atomics: start from zero.
  const PlaneTableHeader zero;
  table.buffer.upload(&zero, sizeof(zero));
  keys_.bind("boxes", scene.boxes());
  keys_.bind("keys", keys_buffer_);
  keys_.bind("values", values_);
  keys_.bind("plane_table", table.buffer);
  const glm::vec3 f = glm::abs(camera.forward());  // as voxel/v2lf.cpp's depth_span
  const GLuint p = keys_.id();
  glProgramUniform1ui(p, keys_.uniform("voxel_count"), GLuint(n));
  glProgramUniformMatrix3fv(p, keys_.uniform("world_to_camera"), 1, GL_FALSE, glm::value_ptr(camera.world_to_camera));
  glProgramUniform3fv(p, keys_.uniform("camera_position"), 1, glm::value_ptr(camera.position_world));
  glProgramUniform1f(p, keys_.uniform("extent_factor"), f.x + f.y + f.z);
  keys_.use();
  keys_.dispatch_1d(n, kVoxelBinningGroupSize);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void GlVoxelBinning::group_orders(const GlVoxelScene& scene, uint32_t octants, int max_planes,
                                  const glm::uvec2& plane_groups, GlPlaneTable& table) {
  const size_t n = scene.size();
  GLint octant_of_slot[kVoxelOctants] = {0, 0, 0, 0, 0, 0, 0, 0}, slot_of_octant[kVoxelOctants];
  GLuint slots = 0;
  for (int octant = 0; octant < int(kVoxelOctants); ++octant) {
    slot_of_octant[octant] = (octants & (1u << octant)) ? GLint(slots) : -1;
    if (octants & (1u << octant)) octant_of_slot[slots++] = octant;
  }
  // Chunk ids 0..max_planes - 1 and max_planes for the unbinned.
  const int chunk_bits = std::bit_width(unsigned(max_planes));
  group_keys_.ensure(std::max<size_t>(n, 1) * sizeof(uint32_t));
  group_sorted_.ensure(std::max<size_t>(n, 1) * sizeof(uint32_t));
  group_values_.ensure(std::max<size_t>(n * slots, 1) * sizeof(uint32_t));

  chunk_of_.bind("values", values_);
  chunk_of_.bind("layers", layers_);
  chunk_of_.bind("plane_table", table.buffer);
  chunk_of_.bind("chunk_of", chunk_of_buffer_);
  glProgramUniform1ui(chunk_of_.id(), chunk_of_.uniform("voxel_count"), GLuint(n));
  glProgramUniform1ui(chunk_of_.id(), chunk_of_.uniform("unbinned"), GLuint(max_planes));
  chunk_of_.use();
  chunk_of_.dispatch_1d(n, kVoxelBinningGroupSize);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  // Per octant in view: its order keyed by chunk, sorted stably, copied to its slot.
  const GLuint p = orders_.id();
  glProgramUniform1ui(p, orders_.uniform("voxel_count"), GLuint(n));
  for (GLuint s = 0; s < slots; ++s) {
    orders_.bind("order", scene.order_buffer());  // the sort binds its own buffers: ours each time
    orders_.bind("keys", group_keys_);
    orders_.bind("values", group_sorted_);
    orders_.bind("chunk_of", chunk_of_buffer_);
    glProgramUniform1ui(p, orders_.uniform("octant"), GLuint(octant_of_slot[s]));
    orders_.use();
    orders_.dispatch_1d(n, kVoxelBinningGroupSize);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    sort_.sort(group_keys_, group_sorted_, uint32_t(n), chunk_bits);
    if (n > 0)
      glCopyNamedBufferSubData(group_sorted_.id(), group_values_.id(), 0, GLintptr(s * n * sizeof(uint32_t)),
                               GLsizeiptr(n * sizeof(uint32_t)));
  }

  draws_pass_.bind("draws", draws_);
  draws_pass_.bind("plane_table", table.buffer);
  const GLuint d = draws_pass_.id();
  glProgramUniform1ui(d, draws_pass_.uniform("voxel_count"), GLuint(n));
  glProgramUniform1ui(d, draws_pass_.uniform("max_planes"), GLuint(max_planes));
  glProgramUniform1iv(d, draws_pass_.uniform("slot_of_octant"), kVoxelOctants, slot_of_octant);
  glProgramUniform2ui(d, draws_pass_.uniform("plane_groups"), plane_groups.x, plane_groups.y);
  draws_pass_.use();
  draws_pass_.dispatch_1d(size_t(max_planes) * kVoxelOctants, kVoxelDrawsGroupSize);
  // Next: the raster (storage reads of the orders and draws, indirect draws), the swizzle.
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

size_t GlVoxelBinning::plane_dispatch_offset(int plane, int max_planes) {
  return (size_t(kVoxelOctants) * size_t(max_planes) + size_t(plane)) * 4 * sizeof(uint32_t);
}

void GlVoxelBinning::run(const GlVoxelScene& scene, const render::ReferenceCamera& ref, int chunks,
                         render::ChunkBinning binning, const glm::uvec2& plane_groups, GlPlaneTable& table) {
  const size_t n = scene.size();
  keys_buffer_.ensure(std::max<size_t>(n, 1) * sizeof(uint32_t));
  values_.ensure(std::max<size_t>(n, 1) * sizeof(uint32_t));
  layers_.ensure(std::max<size_t>(n, 1) * sizeof(uint32_t));
  chunk_of_buffer_.ensure(std::max<size_t>(n, 1) * sizeof(uint32_t));
  draws_.ensure(size_t(table.max_planes) * (kVoxelOctants + 1) * 4 * sizeof(uint32_t));  // the draws, 1 dispatch a plane
  keys(scene, ref.camera, table);
  sort_.sort(keys_buffer_, values_, uint32_t(n), 32);
  chunking_.chunk_sorted(ref, chunks, binning, keys_buffer_, n, layers_, table);
  group_orders(scene, octants_in_view(ref.camera), table.max_planes, plane_groups, table);
  check_gl("V2LF depth binning");
}

}  // namespace lfd::gpu
