#include "gpu/voxels/gl_v2lf.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

#include "gpu/splats/gl_per_view_renderer.hpp"
#include "gpu/splats/gl_plane_raster.hpp"
#include "gpu/gl/gl_quilt_target.hpp"
#include "gpu/planes/shaders/plane_io.h"
#include "gpu/planes/shaders/plane_table_io.h"
#include "gpu/voxels/shaders/voxel_plane_lowpass.comp.glsl.hpp"
#include "util/error.hpp"
#include "voxel/plane_lowpass.hpp"

namespace lfd::gpu {
namespace {

// Work groups of a per-plane pass (low-pass, convert: kPlaneGroupWidth x kPlaneGroupHeight texels each).
glm::uvec2 plane_groups(int width, int height) {
  return {(GLuint(width) + kPlaneGroupWidth - 1) / kPlaneGroupWidth, (GLuint(height) + kPlaneGroupHeight - 1) / kPlaneGroupHeight};
}

// Where each chunk begins in the binned voxels listed chunk by chunk, and one past the last.
std::vector<uint32_t> chunk_starts(const render::DepthChunks& chunks) {
  std::vector<uint32_t> start(chunks.members.size() + 1, 0);
  for (size_t k = 0; k < chunks.members.size(); ++k) start[k + 1] = start[k] + uint32_t(chunks.members[k].size());
  return start;
}

// Each chunk's voxels in every octant order of `octants`, taken from the scene's front-to-back
// orders: for octant slot s and chunk k, entries [s n_b + start_k, s n_b + start_k + count_k)
// of `ids` (n_b: the binned voxels; the slots of the octants in view, in octant order).
struct OctantGroups {
  std::vector<uint32_t> ids;
  std::vector<VoxelOrderRanges> ranges;  // per chunk
};

OctantGroups group_by_octant(const GlVoxelScene& scene, const render::DepthChunks& chunks, uint32_t octants) {
  const int planes = int(chunks.members.size());
  const std::vector<uint32_t> start = chunk_starts(chunks);
  std::vector<int> chunk_of(scene.size(), -1);
  for (int k = 0; k < planes; ++k)
    for (uint32_t v : chunks.members[size_t(k)]) chunk_of[v] = k;
  const uint32_t binned_count = start[size_t(planes)];
  OctantGroups out;
  out.ranges.resize(size_t(planes));
  for (int octant = 0; octant < 8; ++octant) {
    if (!(octants & (1u << octant))) continue;
    const uint32_t base = uint32_t(out.ids.size());
    out.ids.resize(out.ids.size() + binned_count);
    std::vector<uint32_t> next(start.begin(), start.end() - 1);
    for (uint32_t v : scene.order(octant))
      if (chunk_of[v] >= 0) out.ids[base + next[size_t(chunk_of[v])]++] = v;
    for (int k = 0; k < planes; ++k)
      out.ranges[size_t(k)][size_t(octant)] = {base + start[size_t(k)], start[size_t(k) + 1] - start[size_t(k)]};
  }
  return out;
}

// The plane table (gpu/planes/gl_planes.hpp) of the CPU's chunks for an array of `max_planes` layers:
// the plane count, the binned voxels, and per plane d_k and where its voxels begin.
std::vector<uint8_t> plane_table(const render::DepthChunks& chunks, int max_planes) {
  const int planes = int(chunks.members.size());
  const std::vector<uint32_t> start = chunk_starts(chunks);
  std::vector<uint8_t> table(plane_table_bytes(max_planes), 0);
  PlaneTableHeader header;
  header.plane_count = uint32_t(planes);
  header.splats_binned = start[size_t(planes)];
  std::memcpy(table.data(), &header, sizeof(header));
  for (int k = 0; k <= planes; ++k) {
    PlaneTableEntry entry;
    entry.depth = k < planes ? chunks.plane_depth[size_t(k)] : 0.0f;
    entry.begin = start[size_t(k)];
    std::memcpy(table.data() + sizeof(header) + size_t(k) * sizeof(entry), &entry, sizeof(entry));
  }
  return table;
}

}  // namespace

GlV2lfRenderer::GlV2lfRenderer(const GlVoxelScene& scene, const GlInfo& info)
    : scene_(scene),
      info_(info),
      convert_u8_(plane_convert_program("rgba8", true)),
      convert_f16_(plane_convert_program("rgba16f", false)),
      convert_f32_(plane_convert_program("rgba32f", false)),
      lowpass_("v2lf plane low-pass", {{GL_COMPUTE_SHADER, voxel_plane_lowpass_comp_glsl}}, {},
               {image("accumulation", kPlaneAccumulationImage, Access::read_write),
                image("scratch", kPlaneLowpassScratchImage, Access::read_write)}) {}

// How a per-plane pass (filter, convert) is dispatched over plane k: its work groups (16 x 8
// texels each), or with the GPU binning the indirect dispatch it wrote, empty past the frame's
// plane count (gpu/voxels/gl_voxel_binning.hpp).
struct GlV2lfRenderer::PlaneDispatch {
  glm::uvec2 groups;
  const Buffer* indirect = nullptr;
  int max_planes = 0;

  void operator()(const Program& program, int k) const {
    if (!indirect) {
      program.dispatch(groups.x, groups.y);
      return;
    }
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, indirect->id());
    program.dispatch_indirect(GLintptr(GlVoxelBinning::plane_dispatch_offset(k, max_planes)));
  }
};

bool GlV2lfRenderer::prepare_lowpass(float variance_px2) {
  const std::vector<float> kernel = voxel::gaussian_lowpass_kernel(variance_px2);  // the CPU's weights
  if (kernel.empty()) return false;
  const int radius = int(kernel.size() / 2);
  if (radius > kLowpassMaxRadius)
    throw_input_error("V2LF on the GPU: the planes' low-pass filter (sigma {:.1f} texels) is wider than {} texels; "
                      "lower --plane-scale",
                      std::sqrt(variance_px2), kLowpassMaxRadius);
  const int wp = accumulation_.width(), hp = accumulation_.height();
  if (!lowpass_scratch_.id() || lowpass_scratch_.width() != wp || lowpass_scratch_.height() != hp)
    lowpass_scratch_ = Texture(GL_RGBA32F, wp, hp);
  const GLuint p = lowpass_.id();
  glProgramUniform2i(p, lowpass_.uniform("plane_size"), wp, hp);
  glProgramUniform1i(p, lowpass_.uniform("radius"), radius);
  glProgramUniform1fv(p, lowpass_.uniform("kernel"), GLsizei(kernel.size()), kernel.data());
  return true;
}

void GlV2lfRenderer::lowpass(int k, const PlaneDispatch& dispatch) {
  lowpass_.bind("accumulation", accumulation_);
  lowpass_.bind("scratch", lowpass_scratch_);
  lowpass_.use();
  for (int along_y = 0; along_y < 2; ++along_y) {
    glProgramUniform1i(lowpass_.id(), lowpass_.uniform("along_y"), along_y);
    dispatch(lowpass_, k);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  }
}

void GlV2lfRenderer::ensure_planes(PlaneFormat format, int max_planes, int width, int height) {
  if (sweeping_.has_planes(format, max_planes, width, height)) return;
  sweeping_.allocate_planes(format, max_planes, width, height);
  accumulation_ = Texture(GL_RGBA32F, width, height, 1);
  accumulation_framebuffer_.attach(0, accumulation_);
  accumulation_framebuffer_.finish(1);
}

std::vector<VoxelOrderRanges> GlV2lfRenderer::upload_chunk_orders(const GlVoxelScene& scene,
                                                                  const render::DepthChunks& chunks,
                                                                  const render::Camera& camera) {
  OctantGroups groups = group_by_octant(scene, chunks, octants_in_view(camera));
  std::vector<uint32_t>& ids = groups.ids;
  if (ids.empty()) ids.push_back(0);
  if (chunk_orders_.bytes() < ids.size() * sizeof(uint32_t)) chunk_orders_ = Buffer(ids.size() * sizeof(uint32_t));
  chunk_orders_.upload(ids.data(), ids.size() * sizeof(uint32_t));
  return std::move(groups.ranges);
}

SplatRasterTarget GlV2lfRenderer::accumulation_target(const GlPlanes& planes) const {
  SplatRasterTarget target;
  target.framebuffer = accumulation_framebuffer_.id();
  target.image_size = {planes.width, planes.height};
  return target;
}

void GlV2lfRenderer::draw_planes(int count, const ChunkDraw& draw_chunk, float lowpass_variance,
                                 const Buffer* plane_dispatches, GlPlanes& planes) {
  const SplatRasterTarget target = accumulation_target(planes);
  const Program& convert = planes.format == PlaneFormat::kRgba8    ? convert_u8_
                           : planes.format == PlaneFormat::kRgba16f ? convert_f16_
                                                                    : convert_f32_;
  glProgramUniform1ui(convert.id(), convert.uniform("batch_layers"), 1u);
  glProgramUniform2i(convert.id(), convert.uniform("plane_size"), planes.width, planes.height);
  const PlaneDispatch dispatch{plane_groups(planes.width, planes.height), plane_dispatches, planes.max_planes};
  const bool filtered = prepare_lowpass(lowpass_variance);
  // Empty once a frame: each plane's convert pass resets the layer for the next.
  targets_.clear(target);
  for (int k = 0; k < count; ++k) {
    draw_chunk(k, target);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
    if (filtered) lowpass(k, dispatch);
    convert_plane(k, convert, dispatch, planes);
  }
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
}

// Layer k of the planes from the accumulation layer (which the pass resets to empty).
void GlV2lfRenderer::convert_plane(int k, const Program& convert, const PlaneDispatch& dispatch, GlPlanes& planes) {
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
  convert.bind("accumulation", accumulation_);
  convert.bind("planes", planes.texels);
  convert.bind("plane_table", planes.table.buffer);
  glProgramUniform1ui(convert.id(), convert.uniform("batch"), GLuint(k));
  convert.use();
  dispatch(convert, k);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

void GlV2lfRenderer::render_quilt(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout,
                                  const GlV2lfOptions& options, const glm::vec3& background, const Texture& quilt) {
  options.v2lf.check(geometry);
  check_quilt_target("V2LF on the GPU", geometry, layout, quilt);
  run_frame(geometry, options, [&](const GlSweepingPlaneStages& stages) {
    sweeping_.render_quilt(stages, geometry, layout, options.v2lf.planes, background, quilt, options.gpu_timers,
                           "a V2LF frame");
  });
}

void GlV2lfRenderer::render_panel(const render::QuiltGeometry& geometry, const GlV2lfOptions& options,
                                  GlDirectPanel& pass, const interlace::DirectPanelOptions& panel_options,
                                  Texture& panel) {
  options.v2lf.check(geometry);
  run_frame(geometry, options, [&](const GlSweepingPlaneStages& stages) {
    sweeping_.render_planes(
        stages, geometry, options.v2lf.planes,
        [&](const GlPlanes& planes, const render::ReferenceCamera& ref) {
          pass.run(planes, geometry, ref, panel_options, panel);
        },
        options.gpu_timers, "a V2LF direct panel frame");
  });
}

float GlV2lfRenderer::lowpass_variance(const render::QuiltGeometry& geometry, const render::ReferenceCamera& ref,
                                       const render::G2lfOptions& o) const {
  return o.adaptive_filter ? voxel::plane_lowpass_variance(scene_.scene(), geometry, ref, o.plane_scale) : 0.0f;
}

// The CPU path's chunks, uploaded. Split voxels' children are appended to the scene: that scene
// is uploaded for this frame.
GlSweepingPlaneStages GlV2lfRenderer::cpu_binned_stages(const render::QuiltGeometry& geometry,
                                                        const GlV2lfOptions& options) {
  const render::G2lfOptions& o = options.v2lf.planes;
  GlSweepingPlaneStages stages;
  stages.bin = [this, &geometry, &options, &o](const render::ReferenceCamera& ref, GlPlanes& planes) {
    cpu_binned_ =
        voxel::bin_voxels_by_depth(scene_.scene(), geometry, ref, o.chunks, o.binning, options.v2lf.split_levels);
    split_scene_.reset();
    if (cpu_binned_.scene.size() != scene_.size()) split_scene_.emplace(cpu_binned_.scene, info_);
    ranges_ = upload_chunk_orders(split_scene_ ? *split_scene_ : scene_, cpu_binned_.chunks, ref.camera);
    const std::vector<uint8_t> table = plane_table(cpu_binned_.chunks, o.chunks);
    planes.table.buffer.upload(table.data(), table.size());
  };
  stages.draw_planes = [this, &geometry, &o, &options](const render::ReferenceCamera& ref, GlPlanes& planes) {
    const GlVoxelScene& scene = split_scene_ ? *split_scene_ : scene_;
    const glm::vec3& sh_origin = geometry.base.position_world;
    const auto draw = [&] {
      draw_planes(
          int(ranges_.size()),
          [&](int k, const SplatRasterTarget& target) {
            if (options.raster == RasterPath::kCompute)
              tile_raster_->render_view(scene, ref.camera, sh_origin, chunk_orders_, ranges_[size_t(k)], accumulation_,
                                        glm::ivec2(0));
            else
              raster_.draw(scene, ref.camera, sh_origin, chunk_orders_, ranges_[size_t(k)], target);
          },
          lowpass_variance(geometry, ref, o), nullptr, planes);
    };
    draw();
    // The compute path's one read, after the planes: a plane whose keys outgrew the capacity
    // marched nothing, so the planes are drawn again with it grown (docs/gpu.md "Memory and passes").
    if (options.raster == RasterPath::kCompute && tile_raster_->planes_outgrew_capacity()) draw();
  };
  return stages;
}

// The GPU binning: every possible plane drawn through its indirect draws.
GlSweepingPlaneStages GlV2lfRenderer::gpu_binned_stages(const render::QuiltGeometry& geometry,
                                                        const GlV2lfOptions& options) {
  const render::G2lfOptions& o = options.v2lf.planes;
  GlSweepingPlaneStages stages;
  stages.bin = [this, &o](const render::ReferenceCamera& ref, GlPlanes& planes) {
    binning_.run(scene_, ref, o.chunks, o.binning, plane_groups(planes.width, planes.height), planes.table);
  };
  stages.draw_planes = [this, &geometry, &o, &options](const render::ReferenceCamera& ref, GlPlanes& planes) {
    const glm::vec3& sh_origin = geometry.base.position_world;
    if (options.raster == RasterPath::kCompute) {
      // Every plane's keys in one sort, then a plane's run of slots a plane; the one read after the
      // planes: keys that outgrew the capacity are drawn again with it grown (docs/gpu.md "Memory and passes").
      const auto draw = [&] {
        tile_raster_->begin_planes(scene_, ref.camera, sh_origin, binning_.orders(), binning_.chunk_of(),
                                   planes.max_planes);
        draw_planes(
            o.chunks, [&](int k, const SplatRasterTarget&) { tile_raster_->render_plane(k, accumulation_); },
            lowpass_variance(geometry, ref, o), &binning_.draws(), planes);
      };
      draw();
      if (tile_raster_->planes_outgrew_capacity()) draw();
      return;
    }
    raster_.begin_indirect(scene_, ref.camera, sh_origin, binning_.orders(), binning_.draws(),
                           accumulation_target(planes));
    draw_planes(
        o.chunks, [&](int k, const SplatRasterTarget& target) { raster_.draw_indirect(k, target); },
        lowpass_variance(geometry, ref, o), &binning_.draws(), planes);
  };
  return stages;
}

void GlV2lfRenderer::run_frame(const render::QuiltGeometry& geometry, const GlV2lfOptions& options,
                               const std::function<void(const GlSweepingPlaneStages&)>& run) {
  const render::G2lfOptions& o = options.v2lf.planes;
  // The texture limits and the memory budget, as G2LF's planes (no per-Gaussian buffers here).
  GlG2lfOptions plane_options;
  plane_options.g2lf = o;
  plane_options.plane_format = options.plane_format;
  check_g2lf_fits(plane_options, geometry, 0, info_, std::nullopt);
  ensure_planes(options.format(), o.chunks, geometry.base.width * o.plane_scale,
                geometry.base.height * o.plane_scale);
  if (options.raster == RasterPath::kAuto) throw std::logic_error("V2LF on the GPU: resolve the raster path first (auto)");
  if (options.raster == RasterPath::kCompute && !tile_raster_) tile_raster_ = std::make_unique<GlVoxelTileRaster>();
  run(options.bins_on_gpu() ? gpu_binned_stages(geometry, options) : cpu_binned_stages(geometry, options));
  record_stats(options);
}

void GlV2lfRenderer::record_stats(const GlV2lfOptions& options) {
  const GlV2lfStats last = stats_;
  stats_ = {};
  stats_.binned_on_gpu = options.bins_on_gpu();
  const GlVoxelScene& scene = split_scene_ && !stats_.binned_on_gpu ? *split_scene_ : scene_;
  stats_.plane_bytes = sweeping_.planes().texels.bytes();
  stats_.gpu_bytes = scene.bytes() + sweeping_.bytes() + accumulation_.bytes() + lowpass_scratch_.bytes() +
                     chunk_orders_.bytes() + binning_.bytes() + (tile_raster_ ? tile_raster_->bytes() : 0);
  if (!stats_.binned_on_gpu) {
    stats_.planes = int(cpu_binned_.chunks.members.size());
    stats_.voxels_binned = chunk_starts(cpu_binned_.chunks).back();
    stats_.voxels_split = cpu_binned_.voxels_split;
  }
  if (!options.gpu_timers) return;
  const std::optional<GlSweepingPlaneReadout> r = sweeping_.readout(options.timer_reads);
  const bool fresh = r.has_value();
  if (stats_.binned_on_gpu) {
    stats_.planes = fresh ? int(r->header.plane_count) : last.planes;
    stats_.voxels_binned = fresh ? r->header.splats_binned : last.voxels_binned;
  }
  stats_.seconds_binning = fresh ? r->seconds.binning : last.seconds_binning;
  stats_.seconds_planes = fresh ? r->seconds.planes : last.seconds_planes;
  stats_.seconds_swizzle = fresh ? r->seconds.swizzle : last.seconds_swizzle;
  stats_.frames_late = fresh ? r->frames_late : last.frames_late;
}

ImageF render_quilt_v2lf_gl(const scene::VoxelScene& scene, const render::QuiltGeometry& geometry,
                            const render::QuiltLayout& layout, const GlV2lfOptions& options,
                            const glm::vec3& background, GlV2lfStats* stats) {
  options.v2lf.check(geometry);
  const GlInfo info = query_gl_info("current context");
  const GlVoxelScene gl_scene(scene, info);
  GlV2lfRenderer renderer(gl_scene, info);
  const Texture quilt = make_quilt_texture(layout, GL_RGBA32F);
  renderer.render_quilt(geometry, layout, options, background, quilt);
  if (stats) {
    *stats = renderer.stats();
    if (stats->binned_on_gpu) {  // a one-off: the counts read back after the frame
      const PlaneTableHeader header = renderer.planes().table.read_header();
      stats->planes = int(header.plane_count);
      stats->voxels_binned = header.splats_binned;
    }
  }
  return read_image_top_down(quilt, 3);
}

}  // namespace lfd::gpu
