#include "gpu/gl_v2lf.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "gpu/gl_per_view_renderer.hpp"
#include "gpu/gl_plane_raster.hpp"
#include "gpu/shaders/voxel_plane_lowpass.comp.glsl.hpp"
#include "util/error.hpp"
#include "voxel/plane_lowpass.hpp"

namespace lfd::gpu {
namespace {

constexpr GLuint kPlaneTableBinding = 9;  // g2lf_plane_convert.comp.glsl's PlaneTable

}  // namespace

GlV2lfRenderer::GlV2lfRenderer(const GlVoxelScene& scene, const GlInfo& info)
    : scene_(scene),
      info_(info),
      convert_u8_(plane_convert_program("rgba8", true)),
      convert_f16_(plane_convert_program("rgba16f", false)),
      convert_f32_(plane_convert_program("rgba32f", false)),
      lowpass_("v2lf plane low-pass", {{GL_COMPUTE_SHADER, voxel_plane_lowpass_comp_glsl}}) {}

void GlV2lfRenderer::lowpass(float variance_px2) {
  const std::vector<float> kernel = voxel::gaussian_lowpass_kernel(variance_px2);  // the CPU's weights
  if (kernel.empty()) return;
  const int radius = int(kernel.size() / 2);
  if (radius > 64)
    throw_input_error("V2LF on the GPU: the planes' low-pass filter (sigma {:.1f} texels) is wider than 64 texels; "
                      "lower --plane-scale",
                      std::sqrt(variance_px2));
  const int wp = accumulation_.width(), hp = accumulation_.height();
  if (!lowpass_scratch_.id() || lowpass_scratch_.width() != wp || lowpass_scratch_.height() != hp)
    lowpass_scratch_ = Texture(GL_RGBA32F, wp, hp);
  const GLuint p = lowpass_.id();
  glProgramUniform2i(p, lowpass_.uniform("plane_size"), wp, hp);
  glProgramUniform1i(p, lowpass_.uniform("radius"), radius);
  glProgramUniform1fv(p, lowpass_.uniform("kernel"), GLsizei(kernel.size()), kernel.data());
  glBindImageTexture(0, accumulation_.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA32F);
  glBindImageTexture(2, lowpass_scratch_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
  lowpass_.use();
  for (int along_y = 0; along_y < 2; ++along_y) {
    glProgramUniform1i(p, lowpass_.uniform("along_y"), along_y);
    glDispatchCompute(GLuint((wp + 15) / 16), GLuint((hp + 7) / 8), 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  }
}

void GlV2lfRenderer::render_quilt(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout,
                                  const GlV2lfOptions& options, const glm::vec3& background, const Texture& quilt) {
  options.v2lf.check(geometry);
  const render::G2lfOptions& o = options.v2lf.planes;
  layout.check("quilt");
  if (quilt.width() != layout.width || quilt.height() != layout.height || quilt.layers() != 0)
    throw_input_error("V2LF on the GPU: the quilt texture is {}x{}, the layout {}x{}", quilt.width(), quilt.height(),
                      layout.width, layout.height);
  if (geometry.views > layout.cols * layout.rows)
    throw_input_error("V2LF on the GPU: {} views do not fit a quilt of {} tiles", geometry.views,
                      layout.cols * layout.rows);
  // The texture limits and the memory budget, as G2LF's planes (no per-Gaussian buffers here).
  GlG2lfOptions plane_options;
  plane_options.g2lf = o;
  plane_options.plane_format = options.plane_format;
  check_g2lf_fits(plane_options, geometry, 0, info_, std::nullopt);

  // Binning: the CPU path's chunks and reference camera.
  const float d_shift = o.d_shift >= 0.0f ? o.d_shift : render::make_reference_camera(geometry, 0.0f, 1).d_forward;
  const render::ReferenceCamera ref = render::make_reference_camera(geometry, d_shift, o.plane_scale);
  const voxel::VoxelChunks binned =
      voxel::bin_voxels_by_depth(scene_.scene(), geometry, ref, o.chunks, o.binning, options.v2lf.split_levels);
  const render::DepthChunks& chunks = binned.chunks;
  const int planes = int(chunks.members.size());
  // Split voxels' children are appended to the scene: upload that scene for this frame.
  std::optional<GlVoxelScene> split_scene;
  if (binned.scene.size() != scene_.size()) split_scene.emplace(binned.scene, info_);
  const GlVoxelScene& scene = split_scene ? *split_scene : scene_;
  const float lowpass_variance =
      o.adaptive_filter ? voxel::plane_lowpass_variance(scene_.scene(), geometry, ref, o.plane_scale) : 0.0f;

  // Each chunk's voxels in every octant order the reference image needs: for octant slot s
  // and chunk k, entries [s n_b + start_k, s n_b + start_k + count_k) of one buffer.
  const size_t n = scene.size();
  std::vector<int> chunk_of(n, -1);
  std::vector<uint32_t> start(size_t(planes) + 1, 0);
  for (int k = 0; k < planes; ++k) {
    for (uint32_t v : chunks.members[size_t(k)]) chunk_of[v] = k;
    start[size_t(k) + 1] = start[size_t(k)] + uint32_t(chunks.members[size_t(k)].size());
  }
  const uint32_t binned_count = start[size_t(planes)];
  const uint32_t octants = octants_in_view(ref.camera);
  std::vector<uint32_t> grouped;
  std::vector<VoxelOrderRanges> ranges(static_cast<size_t>(planes));
  for (int octant = 0; octant < 8; ++octant) {
    if (!(octants & (1u << octant))) continue;
    const uint32_t base = uint32_t(grouped.size());
    grouped.resize(grouped.size() + binned_count);
    std::vector<uint32_t> next(start.begin(), start.end() - 1);
    for (uint32_t v : scene.order(octant))
      if (chunk_of[v] >= 0) grouped[base + next[size_t(chunk_of[v])]++] = v;
    for (int k = 0; k < planes; ++k)
      ranges[size_t(k)][size_t(octant)] = {base + start[size_t(k)], start[size_t(k) + 1] - start[size_t(k)]};
  }
  if (grouped.empty()) grouped.push_back(0);
  if (chunk_orders_.bytes() < grouped.size() * sizeof(uint32_t)) chunk_orders_ = Buffer(grouped.size() * sizeof(uint32_t));
  chunk_orders_.upload(grouped.data(), grouped.size() * sizeof(uint32_t));

  // Planes: one layer per possible chunk, the table from the CPU's depths.
  const PlaneFormat format = options.format();
  const int wp = ref.camera.width, hp = ref.camera.height;
  if (!planes_.texels.id() || planes_.format != format || planes_.max_planes != o.chunks || planes_.width != wp ||
      planes_.height != hp) {
    planes_ = GlPlanes();
    planes_ = GlPlanes(format, o.chunks, wp, hp);
    accumulation_ = Texture(GL_RGBA32F, wp, hp, 1);
    accumulation_framebuffer_.attach(0, accumulation_);
    accumulation_framebuffer_.finish(1);
  }
  std::vector<uint8_t> table(plane_table_bytes(o.chunks), 0);
  PlaneTableHeader header;
  header.plane_count = uint32_t(planes);
  header.splats_binned = binned_count;
  std::memcpy(table.data(), &header, sizeof(header));
  for (int k = 0; k <= planes; ++k) {
    PlaneTableEntry entry;
    entry.depth = k < planes ? chunks.plane_depth[size_t(k)] : 0.0f;
    entry.begin = start[size_t(k)];
    std::memcpy(table.data() + sizeof(header) + size_t(k) * sizeof(entry), &entry, sizeof(entry));
  }
  planes_.table.buffer.upload(table.data(), table.size());

  SplatRasterTarget target;
  target.framebuffer = accumulation_framebuffer_.id();
  target.image_size = {wp, hp};
  const Program& convert = format == PlaneFormat::kRgba8    ? convert_u8_
                           : format == PlaneFormat::kRgba16f ? convert_f16_
                                                             : convert_f32_;
  glProgramUniform1ui(convert.id(), convert.uniform("batch_layers"), 1u);
  glProgramUniform2i(convert.id(), convert.uniform("plane_size"), wp, hp);
  for (int k = 0; k < planes; ++k) {
    targets_.clear(target);
    raster_.draw(scene, ref.camera, geometry.base.position_world, chunk_orders_, ranges[size_t(k)], target);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
    lowpass(lowpass_variance);
    // Layer k of the planes from the accumulation layer (which the pass resets to empty).
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
    glBindImageTexture(0, accumulation_.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA32F);
    glBindImageTexture(1, planes_.texels.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, gl_internal_format(format));
    planes_.table.buffer.bind_storage(kPlaneTableBinding);
    glProgramUniform1ui(convert.id(), convert.uniform("batch"), GLuint(k));
    convert.use();
    glDispatchCompute(GLuint((wp + 15) / 16), GLuint((hp + 7) / 8), 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  }
  const float outside[4] = {0.0f, 0.0f, 0.0f, 1.0f};  // outside the tiles: 0, as the CPU's
  glClearTexImage(quilt.id(), 0, GL_RGBA, GL_FLOAT, outside);
  swizzle_.run(planes_, geometry, ref, layout, o.filter, background, quilt);
  check_gl("a V2LF frame");

  stats_ = {};
  stats_.planes = planes;
  stats_.voxels_binned = binned_count;
  stats_.voxels_split = binned.voxels_split;
  stats_.plane_bytes = planes_.texels.bytes();
  stats_.gpu_bytes = scene.bytes() + planes_.texels.bytes() + planes_.table.buffer.bytes() + accumulation_.bytes() +
                     lowpass_scratch_.bytes() + chunk_orders_.bytes();
}

ImageF render_quilt_v2lf_gl(const voxel::VoxelScene& scene, const render::QuiltGeometry& geometry,
                            const render::QuiltLayout& layout, const GlV2lfOptions& options,
                            const glm::vec3& background, GlV2lfStats* stats) {
  options.v2lf.check(geometry);
  const GlInfo info = query_gl_info("current context");
  const GlVoxelScene gl_scene(scene, info);
  GlV2lfRenderer renderer(gl_scene, info);
  const Texture quilt = make_quilt_texture(layout, GL_RGBA32F);
  renderer.render_quilt(geometry, layout, options, background, quilt);
  if (stats) *stats = renderer.stats();
  return read_image_top_down(quilt, 3);
}

}  // namespace lfd::gpu
