// The GL voxel path (issues #13, #33) against the exact CPU voxel rasterizer and CPU V2LF on real
// EGL contexts (llvmpipe here): one box's transmittance, views whose rays take several octants,
// per-view quilts with supersampling, and V2LF with every option the CPU path has (split voxels,
// the planes' low-pass filter, u8/f32 planes), each drawn by the raster pipeline and by the
// compute tile rasterizer; V2LF's GPU binning against the CPU's binning (chunks, plane depths,
// grouped orders, draws) and its planes against the CPU-binned GL path's, texel for texel.
// Small images: llvmpipe runs on the CPU.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "gpu/gl/gl_context.hpp"
#include "gpu/splats/gl_per_view_renderer.hpp"
#include "gpu/voxels/gl_v2lf.hpp"
#include "gpu/voxels/gl_voxel_binning.hpp"
#include "gpu/voxels/gl_voxel_scene.hpp"
#include "gpu/voxels/gl_voxel_tile_raster.hpp"
#include "gpu/voxels/gl_voxel_views.hpp"
#include "render/image_metrics.hpp"
#include "../voxel/voxel_test_scenes.hpp"
#include "voxel/v2lf.hpp"
#include "voxel/voxel_generator.hpp"
#include "voxel/voxel_quilt.hpp"
#include "voxel/voxel_rasterizer.hpp"

namespace lfd::gpu {
namespace {

// Both ways of drawing voxels (docs/gpu.md "Voxels on the GPU"): each has the same CPU twin.
constexpr RasterPath kRasterPaths[] = {RasterPath::kHardware, RasterPath::kCompute};

// The PSNR bar against the CPU: the raster pipeline cannot stop a ray at T < 1e-4 (later voxels
// add up to 1e-4 of their colour); the compute path stops where the CPU does, so it is held to
// float rounding (it measures 134-145 dB on these cases).
double bar_db(RasterPath raster, double hardware_db) { return raster == RasterPath::kCompute ? 120.0 : hardware_db; }

HeadlessContext& context() {
  static HeadlessContext c;
  return c;
}

ImageF rgb_of(const render::RasterImage& image) {
  ImageF f(image.width, image.height, 3);
  f.pixels = image.rgb;
  return f;
}

ImageF transmittance_of(const render::RasterImage& image) {
  ImageF f(image.width, image.height, 1);
  f.pixels = image.transmittance;
  return f;
}

// A generated scene (shell, ground, objects; SH degree 1) and a 5-view quilt of 96x72 views.
struct Fixture {
  scene::VoxelScene scene;
  render::QuiltGeometry geometry;
  render::QuiltLayout layout;
};

const Fixture& fixture() {
  static const Fixture f = [] {
    Fixture f;
    voxel::VoxelGeneratorOptions o;
    o.detail_level = 6;
    o.sh_degree = 1;
    f.scene = voxel::generate_voxel_scene(o);
    const render::Camera base =
        render::make_look_at_camera({0, -1.5f, -5.5f}, {0, 0.5f, 0}, {0, -1, 0}, 0.8f, 96, 72);
    f.geometry = render::make_quilt_geometry(base, std::sqrt(2.0f * 2.0f + 6.0f * 6.0f), 40.0f, 5);
    f.layout = render::make_quilt_layout(f.geometry, 5, 1);
    return f;
  }();
  return f;
}

TEST(GlVoxel, OneBoxTransmitsExpOfDensityTimesChord) {
  context().make_current();
  scene::VoxelScene s = voxel::testing::empty_scene();
  const float sigma = 0.02f;
  voxel::testing::add_voxel(s, {0, 0, 0}, 0, voxel::testing::raw_density_for(sigma), {0.8f, 0.4f, 0.2f});
  // Head-on through the middle of the unit root box: the chord is 1.
  const render::Camera camera = voxel::testing::camera_through({0.0f, 0.0f, -3.0f}, {0.0f, 0.0f, 0.0f});
  render::QuiltGeometry geometry = render::make_quilt_geometry(camera, 3.0f, 10.0f, 1);
  for (const RasterPath raster : kRasterPaths) {
    const render::RasterImage gl = render_voxel_view_gl(s, geometry, 0, {}, raster);
    const int centre = (camera.height / 2) * camera.width + camera.width / 2;
    const float expected_t = std::exp(-100.0f * sigma * 1.0f);
    EXPECT_NEAR(gl.transmittance[size_t(centre)], expected_t, 1e-4f) << raster_path_name(raster);
    EXPECT_NEAR(gl.rgb[3 * size_t(centre)], 0.8f * (1.0f - expected_t), 1e-4f) << raster_path_name(raster);
  }
}

TEST(GlVoxel, ViewsMatchTheCpuRasterizerInEveryOctant) {
  context().make_current();
  const Fixture& f = fixture();
  // Rays of the base view, and of a camera inside the shell looking along an axis, whose rays
  // take four octants (x and y of both signs).
  const render::Camera inside = render::make_look_at_camera({0.3f, 0.6f, -1.0f}, {0.3f, 0.6f, 3.0f}, {0, -1, 0}, 1.2f, 80, 64);
  const GlVoxelScene gl_scene(f.scene, query_gl_info("test"));
  for (const RasterPath raster : kRasterPaths) {
    GlVoxelViews views(gl_scene, raster);
    for (const render::Camera& camera : {f.geometry.base, inside}) {
      const uint32_t octants = octants_in_view(camera);
      const render::RasterImage cpu = voxel::rasterize_voxels(f.scene, camera);
      const render::RasterImage gl = views.render_view(camera, {});
      const double rgb_db = render::psnr(rgb_of(gl), rgb_of(cpu));
      const double t_db = render::psnr(transmittance_of(gl), transmittance_of(cpu));
      std::printf("%s, octants 0x%02x: rgb %.1f dB, transmittance %.1f dB\n", raster_path_name(raster), octants,
                  rgb_db, t_db);
      EXPECT_GT(rgb_db, bar_db(raster, 50.0));
      EXPECT_GT(t_db, bar_db(raster, 50.0));
    }
  }
  EXPECT_GE(__builtin_popcount(octants_in_view(inside)), 4);
}

TEST(GlVoxel, PerViewQuiltMatchesTheCpu) {
  context().make_current();
  const Fixture& f = fixture();
  const ImageF cpu = voxel::render_voxel_quilt_per_view(f.scene, f.geometry, f.layout);
  for (const RasterPath raster : kRasterPaths) {
    const ImageF gl = render_voxel_quilt_per_view_gl(f.scene, f.geometry, f.layout, {}, raster);
    const double db = render::psnr(gl, cpu);
    std::printf("per-view voxel quilt, %s: GL vs CPU %.1f dB\n", raster_path_name(raster), db);
    EXPECT_GT(db, bar_db(raster, 50.0));
  }
}

// The compute path draws every view of a quilt in one pass (one sort, one march, one
// downsample); passes split only at the GPU's buffer limits, and splitting must not change a
// texel: here a limit of half the one pass's keys forces several passes (halving a pass whose keys
// do not fit) and one view an atlas.
TEST(GlVoxel, ComputeQuiltViewsGoInOnePassAndPassesDoNotChangeIt) {
  context().make_current();
  const Fixture& f = fixture();
  const GlVoxelScene gl_scene(f.scene, query_gl_info("test"));
  const auto render = [&](size_t pass_limit, int& passes, int& groups, uint64_t& items, uint64_t& keys) {
    GlVoxelViews views(gl_scene, RasterPath::kCompute);
    views.set_pass_limit(pass_limit);
    const Texture quilt(GL_RGBA32F, f.layout.width, f.layout.height);
    views.render_quilt(f.geometry, f.layout, {}, quilt);
    passes = views.passes();
    groups = views.atlas_groups();
    items = views.tile_raster()->items();
    keys = views.tile_raster()->keys();
    return read_image_top_down(quilt, 4);
  };
  int passes = 0, groups = 0;
  uint64_t items = 0, keys = 0;
  const ImageF one = render(0, passes, groups, items, keys);
  std::printf("compute voxel quilt, %d views: %d pass, %d atlas, %llu items, %llu keys\n", f.geometry.views, passes,
              groups, (unsigned long long)items, (unsigned long long)keys);
  EXPECT_EQ(passes, 1);
  EXPECT_EQ(groups, 1);
  ASSERT_GT(keys, 0u);
  // Limit the pass to half the keys (and at least two views' items): several passes, and as few
  // views an atlas as its bytes allow.
  const size_t limit = 4 * std::max<size_t>(keys / 2, 2 * items / size_t(f.geometry.views) + 1);
  const ImageF split = render(limit, passes, groups, items, keys);
  std::printf("with a limit of %zu bytes: %d passes, %d atlases\n", limit, passes, groups);
  EXPECT_GE(passes, 2);
  const float ss = f.scene.supersampling;
  const size_t cell_bytes = size_t(std::lround(ss * float(f.geometry.base.width))) *
                            size_t(std::lround(ss * float(f.geometry.base.height))) * 16;
  const size_t views_an_atlas = std::max<size_t>(1, limit / cell_bytes);
  EXPECT_EQ(size_t(groups), (size_t(f.geometry.views) + views_an_atlas - 1) / views_an_atlas);
  ASSERT_EQ(one.pixels.size(), split.pixels.size());
  EXPECT_EQ(std::memcmp(one.pixels.data(), split.pixels.data(), one.pixels.size() * sizeof(float)), 0);

  // Within one atlas: a limit every view's items fit but not their keys, so the pass is halved
  // after the frame's read of its key total (GlVoxelTileRaster::render_views), into the same atlas texels. The supersampled
  // views, as GlVoxelViews draws them (more keys than items).
  std::vector<render::Camera> cameras;
  for (int view = 0; view < f.geometry.views; ++view) {
    render::Camera c = f.geometry.view_camera(view);
    c.width = int(std::lround(ss * float(c.width)));
    c.height = int(std::lround(ss * float(c.height)));
    cameras.push_back(c);
  }
  const auto atlas = [&](size_t pass_limit, int& tile_passes) {
    GlVoxelTileRaster raster;
    raster.set_pass_limit(pass_limit);
    const Texture target(GL_RGBA32F, cameras[0].width * f.geometry.views, cameras[0].height);
    const float empty[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    glClearTexImage(target.id(), 0, GL_RGBA, GL_FLOAT, empty);
    raster.render_views(gl_scene, cameras, target, f.geometry.views);
    tile_passes = raster.passes();
    items = raster.items();
    keys = raster.keys();
    return read_image_top_down(target, 4);
  };
  int whole_passes = 0, halved_passes = 0;
  const ImageF whole = atlas(0, whole_passes);
  ASSERT_GT(keys, items);  // the fixture's supersampled views: more keys than items
  const size_t items_only = 4 * std::max<size_t>(items, keys / 2 + 1);
  const ImageF halved = atlas(items_only, halved_passes);
  std::printf("tile raster alone: %d pass; with a limit of %zu bytes (every item, not every key): %d passes\n",
              whole_passes, items_only, halved_passes);
  EXPECT_EQ(whole_passes, 1);
  EXPECT_GE(halved_passes, 2);
  ASSERT_EQ(whole.pixels.size(), halved.pixels.size());
  EXPECT_EQ(std::memcmp(whole.pixels.data(), halved.pixels.data(), whole.pixels.size() * sizeof(float)), 0);
}

// The Gaussians' recovery, for voxels (docs/gpu.md "Memory and passes"): keys go into buffers of a
// capacity kept from frame to frame, nothing is read back inside a frame, and a pass whose keys
// outgrew the capacity marches nothing and is drawn again after the frame's one read. From a
// capacity of 64 keys the fixture's one pass of every view overflows and is redrawn, and the
// atlas is the one drawn with room to spare, bit for bit; the next frame redraws nothing.
TEST(GlVoxel, ComputePassesWhoseKeysOutgrowTheCapacityAreDrawnAgain) {
  context().make_current();
  const Fixture& f = fixture();
  const GlVoxelScene gl_scene(f.scene, query_gl_info("test"));
  std::vector<render::Camera> cameras;
  for (int view = 0; view < f.geometry.views; ++view) cameras.push_back(f.geometry.view_camera(view));
  const auto draw = [&](GlVoxelTileRaster& raster) {
    const Texture target(GL_RGBA32F, cameras[0].width * f.geometry.views, cameras[0].height);
    const float empty[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    glClearTexImage(target.id(), 0, GL_RGBA, GL_FLOAT, empty);
    raster.render_views(gl_scene, cameras, target, f.geometry.views);
    return read_image_top_down(target, 4);
  };
  GlVoxelTileRaster roomy;
  roomy.set_key_capacity(10'000'000);
  const ImageF truth = draw(roomy);
  EXPECT_EQ(roomy.redrawn_passes(), 0);
  ASSERT_GT(roomy.keys(), 64u);
  GlVoxelTileRaster tight;
  tight.set_key_capacity(64);
  const ImageF redrawn = draw(tight);
  std::printf("voxel tile raster: %llu keys in %d passes, %d redrawn; capacity grown from 64 to %u\n",
              (unsigned long long)tight.keys(), tight.passes(), tight.redrawn_passes(), tight.key_capacity());
  EXPECT_EQ(tight.passes(), 1);
  EXPECT_EQ(tight.redrawn_passes(), 1);
  EXPECT_EQ(tight.keys(), roomy.keys());
  EXPECT_GE(tight.key_capacity(), tight.keys());
  ASSERT_EQ(redrawn.pixels.size(), truth.pixels.size());
  EXPECT_EQ(std::memcmp(redrawn.pixels.data(), truth.pixels.data(), truth.pixels.size() * sizeof(float)), 0);
  const ImageF again = draw(tight);
  EXPECT_EQ(tight.redrawn_passes(), 0);
  EXPECT_EQ(std::memcmp(again.pixels.data(), truth.pixels.data(), truth.pixels.size() * sizeof(float)), 0);
}

TEST(GlVoxel, V2lfMatchesTheCpuWithEveryOption) {
  context().make_current();
  const Fixture& f = fixture();
  struct Case {
    const char* name;
    render::PlanePrecision precision;
    render::PlaneFilter filter;
    int chunks, plane_scale, split_levels;
    bool lowpass;
  };
  for (const Case& c : {Case{"u8 nearest, 16 chunks, split, low-pass", render::PlanePrecision::kU8,
                             render::PlaneFilter::kNearest, 16, 1, 1, true},
                        Case{"f32 bilinear, 32 chunks, Ps 2, no split, no low-pass", render::PlanePrecision::kF32,
                             render::PlaneFilter::kBilinear, 32, 2, 0, false},
                        Case{"u8 bilinear, 64 chunks, no split, low-pass", render::PlanePrecision::kU8,
                             render::PlaneFilter::kBilinear, 64, 1, 0, true}}) {
    GlV2lfOptions options;
    options.v2lf.planes.chunks = c.chunks;
    options.v2lf.planes.plane_scale = c.plane_scale;
    options.v2lf.planes.precision = c.precision;
    options.v2lf.planes.filter = c.filter;
    options.v2lf.planes.adaptive_filter = c.lowpass;
    options.v2lf.split_levels = c.split_levels;
    voxel::V2lfStats cpu_stats;
    const ImageF cpu =
        voxel::render_quilt_v2lf(f.scene, f.geometry, f.layout, options.v2lf, f.scene.background, &cpu_stats);
    for (const RasterPath raster : kRasterPaths) {
      options.raster = raster;
      GlV2lfStats stats;
      const ImageF gl = render_quilt_v2lf_gl(f.scene, f.geometry, f.layout, options, f.scene.background, &stats);
      const double db = render::psnr(gl, cpu);
      std::printf("V2LF %s, %s: GL vs CPU %.1f dB (%d planes, %zu voxels binned, %zu split)\n", c.name,
                  raster_path_name(raster), db, stats.planes, stats.voxels_binned, stats.voxels_split);
      EXPECT_GT(db, bar_db(raster, 45.0)) << c.name << ", " << raster_path_name(raster);
      EXPECT_EQ(stats.binned_on_gpu, c.split_levels == 0);  // split voxels bin on the CPU
      EXPECT_EQ(stats.planes, cpu_stats.planes);  // the CPU's binning, split voxels included
      EXPECT_EQ(stats.voxels_binned, cpu_stats.voxels_binned);
      if (c.split_levels > 0) {
        EXPECT_GT(stats.voxels_split, 0u);
      }
    }
  }
}

// ---- V2LF's binning on the GPU against voxel::bin_voxels_by_depth ----

// The reference camera of the fixture's quilt, or one standing inside the scene: its image plane
// cuts through voxels, so some binned voxels (a corner in front) have their centre behind it
// (negative depths: the signed sort keys).
render::ReferenceCamera reference_for(bool inside, float d_shift) {
  const Fixture& f = fixture();
  if (!inside) {
    render::G2lfOptions o;
    o.d_shift = d_shift;
    return render::reference_camera(o, f.geometry);
  }
  render::ReferenceCamera ref;
  ref.camera = render::make_look_at_camera({0.1f, 0.3f, 0.05f}, {0.3f, 0.5f, 4.0f}, {0, -1, 0}, 1.2f, 96, 72);
  ref.d_forward = ref.d_forward_eff = 0.5f;
  return ref;
}

struct VoxelBinningCase {
  int chunks;
  render::ChunkBinning binning;
  bool inside;
  float d_shift;
};

class GlVoxelBinningCases : public ::testing::TestWithParam<VoxelBinningCase> {};

TEST_P(GlVoxelBinningCases, SameChunksDepthsOrdersAndDrawsAsTheCpu) {
  const VoxelBinningCase& c = GetParam();
  HeadlessContext& ctx = context();
  ctx.make_current();
  const Fixture& f = fixture();
  const render::ReferenceCamera ref = reference_for(c.inside, c.d_shift);
  const voxel::VoxelChunks cpu = voxel::bin_voxels_by_depth(f.scene, f.geometry, ref, c.chunks, c.binning);
  if (c.inside) {  // the case this camera is for: a binned centre behind the camera
    bool behind = false;
    for (uint32_t v : cpu.chunks.members.front()) behind = behind || ref.camera.to_camera(f.scene.voxel_center(v)).z < 0;
    ASSERT_TRUE(behind);
  }

  const GlVoxelScene scene(f.scene, ctx.info());
  GlPlaneTable table(c.chunks);
  GlVoxelBinning binning;
  binning.run(scene, ref, c.chunks, c.binning, glm::uvec2(3, 5), table);
  const PlaneTableHeader header = table.read_header();
  const std::vector<PlaneTableEntry> entries = table.read_entries();
  size_t cpu_binned = 0;
  for (const auto& m : cpu.chunks.members) cpu_binned += m.size();
  ASSERT_EQ(header.splats_binned, cpu_binned);
  ASSERT_EQ(header.plane_count, cpu.chunks.members.size());
  EXPECT_EQ(entries.back().begin, header.splats_binned);

  // Per octant in view: chunk k's voxels in that octant's order, as the CPU path groups them.
  const size_t n = f.scene.size();
  const uint32_t octants = octants_in_view(ref.camera);
  const int slots = std::popcount(octants);
  const auto orders = binning.orders().download_as<uint32_t>(n * size_t(slots));
  const auto draws = binning.draws().download_as<uint32_t>(size_t(c.chunks) * 9 * 4);
  // The per-plane passes' dispatches: the plane's groups, none past the plane count.
  for (int k = 0; k < c.chunks; ++k) {
    const uint32_t* groups = draws.data() + GlVoxelBinning::plane_dispatch_offset(k, c.chunks) / sizeof(uint32_t);
    const bool used = size_t(k) < cpu.chunks.members.size();
    EXPECT_EQ(groups[0], used ? 3u : 0u) << k;
    EXPECT_EQ(groups[1], used ? 5u : 0u) << k;
    EXPECT_EQ(groups[2], used ? 1u : 0u) << k;
  }
  for (size_t k = 0; k < cpu.chunks.members.size(); ++k) {
    EXPECT_EQ(entries[k].depth, cpu.chunks.plane_depth[k]) << "plane " << k;  // bit-exact
    const std::vector<uint32_t>& members = cpu.chunks.members[k];  // sorted by index
    const uint32_t begin = entries[k].begin, count = entries[k + 1].begin - begin;
    ASSERT_EQ(count, members.size()) << "plane " << k;
    int slot = 0;
    for (int octant = 0; octant < 8; ++octant) {
      const uint32_t* draw = draws.data() + (8 * k + size_t(octant)) * 4;
      if (!(octants & (1u << octant))) {
        EXPECT_EQ(draw[1], 0u);
        continue;
      }
      std::vector<uint32_t> expected;
      for (uint32_t v : scene.order(octant))
        if (std::binary_search(members.begin(), members.end(), v)) expected.push_back(v);
      const auto first = orders.begin() + std::ptrdiff_t(size_t(slot) * n + begin);
      EXPECT_EQ(std::vector<uint32_t>(first, first + count), expected) << "plane " << k << ", octant " << octant;
      EXPECT_EQ(draw[0], 4u);
      EXPECT_EQ(draw[1], count);
      EXPECT_EQ(draw[3], uint32_t(slot) * n + begin);
      ++slot;
    }
  }
  for (size_t k = cpu.chunks.members.size(); k < size_t(c.chunks); ++k)
    for (int octant = 0; octant < 8; ++octant) EXPECT_EQ(draws[(8 * k + size_t(octant)) * 4 + 1], 0u) << k;
}

INSTANTIATE_TEST_SUITE_P(Cases, GlVoxelBinningCases,
                         ::testing::Values(VoxelBinningCase{1, render::ChunkBinning::kQuantile, false, 0.0f},
                                           VoxelBinningCase{16, render::ChunkBinning::kQuantile, false, 0.0f},
                                           VoxelBinningCase{64, render::ChunkBinning::kMixed, false, -1.0f},
                                           VoxelBinningCase{7, render::ChunkBinning::kMixed, false, 0.5f},
                                           VoxelBinningCase{512, render::ChunkBinning::kQuantile, false, 0.0f},
                                           VoxelBinningCase{32, render::ChunkBinning::kQuantile, true, 0.0f},
                                           VoxelBinningCase{32, render::ChunkBinning::kMixed, true, 0.0f}));

// The same frame binned on the GPU and on the CPU (uploaded) draws the same voxels in the same
// order into each plane: the planes and the quilts are equal texel for texel.
TEST(GlVoxel, GpuBinnedPlanesEqualTheCpuBinnedOnes) {
  HeadlessContext& ctx = context();
  ctx.make_current();
  const Fixture& f = fixture();
  const GlVoxelScene scene(f.scene, ctx.info());
  for (const render::ChunkBinning binning : {render::ChunkBinning::kQuantile, render::ChunkBinning::kMixed}) {
    GlV2lfOptions options;
    options.v2lf.planes.chunks = 24;
    options.v2lf.planes.binning = binning;
    options.v2lf.planes.precision = render::PlanePrecision::kF32;
    options.v2lf.planes.filter = render::PlaneFilter::kBilinear;
    std::vector<std::vector<float>> planes[2];
    ImageF quilts[2];
    for (const bool on_gpu : {false, true}) {
      options.gpu_binning = on_gpu;
      GlV2lfRenderer renderer(scene, ctx.info());
      const Texture quilt = make_quilt_texture(f.layout, GL_RGBA32F);
      renderer.render_quilt(f.geometry, f.layout, options, f.scene.background, quilt);
      EXPECT_EQ(renderer.stats().binned_on_gpu, on_gpu);
      // Timed frames bring the GPU binning's counts through the frame ring (read at once here).
      options.gpu_timers = true;
      renderer.render_quilt(f.geometry, f.layout, options, f.scene.background, quilt);
      options.gpu_timers = false;
      const voxel::VoxelChunks cpu = voxel::bin_voxels_by_depth(
          f.scene, f.geometry, render::reference_camera(options.v2lf.planes, f.geometry), options.v2lf.planes.chunks,
          binning);
      EXPECT_EQ(renderer.stats().planes, int(cpu.chunks.members.size()));
      size_t binned = 0;
      for (const auto& m : cpu.chunks.members) binned += m.size();
      EXPECT_EQ(renderer.stats().voxels_binned, binned);
      for (int k = 0; k < options.v2lf.planes.chunks; ++k)
        planes[on_gpu].push_back(read_texture_rgba(renderer.planes().texels, k));
      quilts[on_gpu] = read_image_top_down(quilt, 3);
    }
    const int used = int(voxel::bin_voxels_by_depth(f.scene, f.geometry,
                                                    render::reference_camera(options.v2lf.planes, f.geometry),
                                                    options.v2lf.planes.chunks, binning)
                             .chunks.members.size());
    for (int k = 0; k < used; ++k) EXPECT_EQ(planes[1][size_t(k)], planes[0][size_t(k)]) << "plane " << k;
    // Bit for bit (memcmp: the quantile case's first plane sits at base depth ~0, behind the
    // reference camera, where the GL swizzle writes NaN on both paths; the CPU's does not).
    ASSERT_EQ(quilts[1].pixels.size(), quilts[0].pixels.size());
    EXPECT_EQ(std::memcmp(quilts[1].pixels.data(), quilts[0].pixels.data(), quilts[0].pixels.size() * sizeof(float)), 0);
  }
}

}  // namespace
}  // namespace lfd::gpu
