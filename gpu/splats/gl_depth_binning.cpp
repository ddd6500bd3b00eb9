#include "gpu/splats/gl_depth_binning.hpp"

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "gpu/splats/gl_splat_preprocess.hpp"
#include "gpu/splats/shaders/binning_chunks.comp.glsl.hpp"
#include "gpu/splats/shaders/binning_cuts.comp.glsl.hpp"
#include "gpu/splats/shaders/binning_keys.comp.glsl.hpp"
#include "gpu/splats/shaders/binning_layers.comp.glsl.hpp"

namespace lfd::gpu {
namespace {

// A pass that reads depths from sorted keys: depth_key.glsl with the keys' encoding first.
Program depth_pass(const char* label, const char* source, DepthKeys keys, std::vector<Binding> bindings) {
  return Program(label, {{GL_COMPUTE_SHADER, source}},
                 {keys == DepthKeys::kSigned ? "SIGNED_DEPTH_KEYS 1" : "SIGNED_DEPTH_KEYS 0"}, std::move(bindings));
}

}  // namespace

GlDepthBinning::GlDepthBinning(DepthKeys keys)
    : keys_("g2lf binning: keys", {{GL_COMPUTE_SHADER, binning_keys_comp_glsl}}, {},
            {storage_buffer("positions", kScenePositionsBinding, Access::read),
             storage_buffer("keys", kSplatKeysBinding, Access::write),
             storage_buffer("values", kSplatValuesBinding, Access::write),
             storage_buffer("plane_table", kPlaneTableBinding, Access::read_write)}),
      cuts_(depth_pass("depth binning: cuts", binning_cuts_comp_glsl, keys,
                       {storage_buffer("keys", kSplatKeysBinding, Access::read),
                        storage_buffer("plane_table", kPlaneTableBinding, Access::read),
                        storage_buffer("cuts", kBinningCutsBinding, Access::write)})),
      chunks_(depth_pass("depth binning: chunks", binning_chunks_comp_glsl, keys,
                         {storage_buffer("keys", kSplatKeysBinding, Access::read),
                          storage_buffer("draw", kSplatDrawBinding, Access::read_write),
                          storage_buffer("plane_table", kPlaneTableBinding, Access::read_write),
                          storage_buffer("cuts", kBinningCutsBinding, Access::read)})),
      layers_("g2lf binning: layers", {{GL_COMPUTE_SHADER, binning_layers_comp_glsl}}, {},
              {storage_buffer("plane_table", kPlaneTableBinding, Access::read),
               storage_buffer("layers", kSplatLayersBinding, Access::write)}),
      cut_positions_(sizeof(uint32_t) * (kBinningMaxCuts + 1)),
      unused_draw_(sizeof(DrawArraysIndirect)) {}

void GlDepthBinning::run(const GlScene& scene, const render::ReferenceCamera& ref, int chunks,
                         render::ChunkBinning binning, GlRadixSort& sort, Buffer& keys,
                         Buffer& values, Buffer& layers, GlPlaneTable& table, const Buffer* draw, bool binned_only) {
  if (chunks < 1 || chunks > int(kBinningMaxChunks) || chunks > table.max_planes)
    throw std::logic_error("GlDepthBinning: chunks outside 1..min(" + std::to_string(kBinningMaxChunks) +
                           ", table.max_planes)");
  const size_t n = scene.size();
  keys.ensure(n * sizeof(uint32_t));
  values.ensure(n * sizeof(uint32_t));
  layers.ensure(n * sizeof(uint32_t));
  const render::Camera& cam = ref.camera;

  // The header counts binned splats with atomics: start from zero.
  const PlaneTableHeader zero;
  table.buffer.upload(&zero, sizeof(zero));

  {
    const GLuint p = keys_.id();
    glProgramUniform1ui(p, keys_.uniform("gaussian_count"), GLuint(n));
    glProgramUniformMatrix3fv(p, keys_.uniform("world_to_camera"), 1, GL_FALSE,
                              glm::value_ptr(cam.world_to_camera));
    glProgramUniform3fv(p, keys_.uniform("camera_position"), 1, glm::value_ptr(cam.position_world));
    glProgramUniform2f(p, keys_.uniform("limit"), 1.3f * cam.tan_half_fov_x(), 1.3f * cam.tan_half_fov_y());
    keys_.use();
    keys_.bind("positions", scene.positions());
    keys_.bind("keys", keys);
    keys_.bind("values", values);
    keys_.bind("plane_table", table.buffer);
    keys_.dispatch_1d(n, kBinningKeysGroupSize);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  SortKeys how;
  how.drop_culled = binned_only;
  sort.sort(keys, values, uint32_t(n), how);
  chunk_sorted(ref, chunks, binning, keys, n, layers, table, draw);
}

void GlDepthBinning::chunk_sorted(const render::ReferenceCamera& ref, int chunks, render::ChunkBinning binning,
                                  const Buffer& keys, size_t n, Buffer& layers, GlPlaneTable& table,
                                  const Buffer* draw) {
  if (chunks < 1 || chunks > int(kBinningMaxChunks) || chunks > table.max_planes)
    throw std::logic_error("GlDepthBinning: chunks outside 1..min(" + std::to_string(kBinningMaxChunks) +
                           ", table.max_planes)");
  layers.ensure(n * sizeof(uint32_t));
  const bool mixed = binning == render::ChunkBinning::kMixed;
  const GLuint count_chunks = GLuint(mixed ? chunks - chunks / 2 : chunks);
  const GLuint disparity_chunks = GLuint(mixed ? chunks / 2 : 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  for (const Program* program : {&cuts_, &chunks_}) {
    const GLuint p = program->id();
    glProgramUniform1ui(p, program->uniform("count_chunks"), count_chunks);
    glProgramUniform1ui(p, program->uniform("disparity_chunks"), disparity_chunks);
    glProgramUniform1f(p, program->uniform("d_forward_eff"), ref.d_forward_eff);
  }
  cuts_.use();
  cuts_.bind("keys", keys);
  cuts_.bind("plane_table", table.buffer);
  cuts_.bind("cuts", cut_positions_);
  cuts_.dispatch((count_chunks + disparity_chunks + kBinningCutsGroupSize - 1) / kBinningCutsGroupSize);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  chunks_.use();
  chunks_.bind("keys", keys);
  chunks_.bind("draw", draw ? *draw : unused_draw_);
  chunks_.bind("plane_table", table.buffer);
  chunks_.bind("cuts", cut_positions_);
  chunks_.dispatch(1);  // one work group merges every cut
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  layers_.use();
  layers_.bind("plane_table", table.buffer);
  layers_.bind("layers", layers);
  layers_.dispatch_1d(n, kBinningLayersGroupSize);
  // Next: the layered raster (storage reads, indirect draw), the swizzle, read-backs.
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  check_gl("G2LF depth binning");
}

}  // namespace lfd::gpu
