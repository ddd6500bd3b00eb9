#pragma once
// The compute tile rasterizer of Gaussians (--raster compute; docs/gpu.md "The compute tile
// rasterizer"): the reference 3DGS forward pass (forward.cu: preprocess, (tile | depth) keys,
// a sort, per-tile ranges, per-tile compositing in shared memory) in compute shaders, for every
// view of a quilt at once: no per-view loop on the CPU, so the whole chip works where only a few
// SMs rasterize (H100/H200). Per frame:
//   preprocess  every (view, Gaussian) entry in one dispatch (z = view), projected exactly as the
//               per-view preprocess (gpu/splats/shaders/splat_project.glsl); its depth key
//   depth sort  GlRadixSort of every entry's depth key, culled ones dropped: the items, front to
//               back, all views mixed (32-bit float keys: the exact order, ties by entry)
//   keys        per item the tiles its opacity-aware ellipse covers (splat_tile_cover.glsl),
//               counted, scanned and written as slot keys (view * tiles + tile); items with big
//               rectangles by a whole work group each (splat_tile_huge.comp.glsl)
//   tile sort   GlTileKeys: a stable sort by slot, so each (view, tile) lists its splats front
//               to back, and the ranges
//   composite   one work group a (view, tile): batches of 256 splats in shared memory, the
//               reference's alpha rules and early stop, written into the view's quilt cell; a
//               tile with more than split_keys() splats in parts of that many, a work group each,
//               merged front to back after (docs/gpu.md "Balancing")
// Nothing is read back inside a frame: the keys go into buffers of a capacity kept from frame to
// frame (GlTileKeys::scan_to_capacity), each pass's key total is copied on the GPU, and the CPU
// reads the totals once, after the whole frame is issued; a pass whose keys outgrew the capacity is
// drawn again with it grown (docs/gpu.md "Memory and passes"). Equal to the CPU rasterizer to rounding:
// the depth order is the exact one and the keys skip only tiles the reference blends nothing in.
#include <cstddef>
#include <functional>
#include <map>
#include <span>
#include <tuple>
#include <utility>
#include <vector>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "gpu/gl/gl_objects.hpp"
#include "gpu/planes/gl_planes.hpp"
#include "gpu/gl/gl_program.hpp"
#include "gpu/splats/gl_scene.hpp"
#include "gpu/compute/gl_key_capacity.hpp"
#include "gpu/compute/gl_tile_keys.hpp"
#include "gpu/splats/shaders/splat_tile_io.h"
#include "render/camera.hpp"
#include "render/preprocess.hpp"

namespace lfd::gpu {

// Where the views go: view v into cell (v % cols, v / cols) of `texture` (cells cell_size,
// bottom-up: cell row r starts at GL row r * cell height, the view's top row at the cell's top),
// cropped to the cell; rgb = C + T background, alpha = T (TargetAlpha::kTransmittance: one view's
// image) or 1 (kOpaque: a quilt).
struct TileViewsTarget {
  Texture* texture = nullptr;  // RGBA32F, RGBA16F or RGBA8
  int cols = 1;
  glm::ivec2 cell_size{0, 0};
  glm::vec3 background{0.0f};
  TargetAlpha alpha = TargetAlpha::kOpaque;
};

// What the last frame held (for the benchmarks and the tests).
struct TileSplatCounts {
  size_t entries = 0;  // views x Gaussians
  uint32_t keys = 0;   // (slot, splat) keys after the ellipse test
  uint32_t slots = 0;  // views x tiles
};

class GlSplatTileRaster {
 public:
  GlSplatTileRaster();  // needs a current context; compiles the passes

  // Renders every camera (one image size) into its cell of `target`, in one pass when the
  // records fit a storage buffer, else in passes of as many views as fit. `stamp(k)`, when given,
  // is called after the first pass's preprocess (k = 1) and keys and sorts (2), and at the end (3),
  // for GPU timers.
  void render_views(const GlScene& scene, std::span<const render::Camera> cameras,
                    const render::RasterSettings& settings, const TileViewsTarget& target,
                    const std::function<void(int)>& stamp = {});

  // G2LF's planes (--raster compute; the twin of GlPlaneRaster::run): the items are the binned
  // splats in `sorted_ids` (the binning's depth order), their records in `records` (preprocessed
  // from the reference camera at the planes' size), their planes in `layers`, their count the
  // instance count of `draw` (a DrawArraysIndirect). Keys (plane | tile); every layer of `planes`
  // is cleared to (C, T) = (0, 0, 0, 1) and only the non-empty (plane, tile) slots are
  // composited (the work list's indirect dispatch), each into its layer in the planes' format
  // (RGBA8 rounded once from the float sums, as the CPU stores u8 planes).
  void render_planes(const Buffer& records, const Buffer& sorted_ids, const Buffer& layers, const Buffer& draw,
                     size_t gaussians, GlPlanes& planes, const std::function<void(int)>& stamp = {});

  // The largest storage buffer one pass may bind, in bytes (its (view, Gaussian) records, a
  // SplatRecord an entry): the views of a frame go in as few passes as this allows (one when they
  // fit). 0 (the default): GL_MAX_SHADER_STORAGE_BLOCK_SIZE (2 GiB on NVIDIA: 45 views of 740k
  // Gaussians). The same unit and default as GlVoxelTileRaster::set_pass_limit.
  void set_pass_limit(size_t bytes) { pass_limit_ = bytes; }
  size_t pass_limit() const;
  // Passes the last render_views took.
  int passes() const { return passes_; }
  // A slot (image, tile) with more keys than this is composited in parts of this many keys, a
  // work group each, then merged (docs/gpu.md "Balancing"); 0: never split. Default
  // kTileSplatSplitKeys.
  void set_split_keys(uint32_t keys) { split_keys_ = keys; }
  uint32_t split_keys() const { return split_keys_; }
  // Keys the key buffers hold: kept from frame to frame, first a key an item, grown to a quarter
  // over a frame's total when a pass's keys did not fit (that pass is drawn again). Setting it
  // (tests) starts from another capacity.
  void set_key_capacity(uint32_t keys) { capacity_.set_keys(keys); }
  uint32_t key_capacity() const { return capacity_.keys(); }
  // Passes of the last render_views or render_planes drawn again because their keys outgrew the
  // capacity.
  int redrawn_passes() const { return redrawn_; }

  const TileSplatCounts& counts() const { return counts_; }
  // GPU bytes the planes' path (render_planes) holds for `items` items, `slots` (plane, tile)
  // slots and `keys` keys: the per-item counts and huge list, the keys and values with the tile
  // sort's copies, the ranges and work list, and the split list with its partials (for memory
  // checks before a frame; docs/gpu.md "Memory and passes").
  static size_t plane_path_bytes(size_t items, size_t slots, size_t keys);
  // The items whose keys were written by a work group each in the last frame (waits for the GPU).
  uint32_t read_huge_items() const;
  // The slots split into parts in the last pass, and their parts (waits for the GPU; 0, 0 when
  // nothing was split).
  std::pair<uint32_t, uint32_t> read_split_counts() const;
  size_t bytes() const;

 private:
  // One pass: `cameras`, views first_view.. of the target.
  void render_pass(const GlScene& scene, std::span<const render::Camera> cameras, uint32_t first_view, uint32_t pass,
                   const render::RasterSettings& settings, const TileViewsTarget& target,
                   const std::function<void(int)>& stamp);
  // The key passes of views (PLANES 0) or planes (PLANES 1).
  struct KeyPrograms {
    Program count, emit, huge_count, huge_emit;
    explicit KeyPrograms(TileImages images);
  };
  // What a compositing pass takes of a slot: the whole list into the target, or a split slot's
  // parts into partials (merged after; docs/gpu.md "Balancing").
  enum class SlotShare { kWhole, kSplitParts };
  // What the key passes read: the records, the items (record indices, front to back), where the
  // item count is (a uint of `kept`) and, for planes, each item's plane.
  struct Items {
    const Buffer* records = nullptr;
    const Buffer* entries = nullptr;
    const Buffer* kept = nullptr;
    uint32_t kept_word = 0;
    const Buffer* layers = nullptr;
    uint32_t capacity = 0;  // items dispatched
  };
  // Counts, scans, writes, sorts and ranges the keys of `items` (small items per invocation,
  // huge ones per work group) into buffers of the kept capacity's keys, and records the key
  // total as pass `pass`'s (GlKeyCapacity); nothing is read back.
  void make_keys(const KeyPrograms& programs, const Items& items, uint32_t gaussians, glm::ivec2 tile_grid,
                 uint32_t slots, uint32_t pass);
  // GlKeyCapacity::read_frame (the frame's one read), its key sum into counts_.keys; the passes
  // whose keys outgrew the capacity.
  std::vector<uint32_t> overflowed_passes(uint32_t passes);
  // One pass of render_planes.
  void draw_planes(const Buffer& records, const Buffer& sorted_ids, const Buffer& layers, const Buffer& draw,
                   size_t gaussians, GlPlanes& planes, const std::function<void(int)>& stamp);
  // Counts (EMIT 0) or writes (EMIT 1).
  void run_keys(const KeyPrograms& programs, KeyStep step, const Items& items, uint32_t gaussians,
                glm::ivec2 tile_grid);
  // The compositing of whole slots (into `format`) or of split slots' parts, for views or
  // planes; and the split slots' merge into `format`.
  const Program& composite_program(GLenum format, TileImages images, SlotShare share = SlotShare::kWhole);
  const Program& merge_program(GLenum format, TileImages images);
  // Where the compositing writes: the views of `target` from first_view, or planes (views null).
  struct TargetUniforms {
    glm::ivec2 image_size{0, 0}, tile_grid{0, 0};
    const TileViewsTarget* views = nullptr;
    uint32_t first_view = 0;
  };
  static void set_target_uniforms(const Program& program, const TargetUniforms& target);
  // The split of hot slots (after make_keys): lists the slots over split_keys_ keys and empties
  // their ranges; returns false (and does nothing) when no slot can be over it (`keys` in all).
  bool split_slots(uint32_t keys, uint32_t slots);
  // The split slots' parts, then their merge into the target image (after the compositing).
  void composite_split(GLenum format, TileImages images, const TargetUniforms& target, const Buffer& records,
                       const Texture& target_texture);

  Program preprocess_, split_;
  KeyPrograms view_keys_, plane_keys_;
  std::map<std::tuple<GLenum, TileImages, SlotShare>, Program> composite_;
  std::map<std::pair<GLenum, TileImages>, Program> merge_;
  GlTileKeys tiles_;
  GlKeyCapacity capacity_;
  Buffer views_, records_, entry_keys_, entries_, huge_, split_list_, partials_;
  int redrawn_ = 0;
  uint32_t split_keys_ = kTileSplatSplitKeys;
  bool split_ran_ = false;  // the last pass split slots (split_list_ holds its counts)
  TileSplatCounts counts_;
  size_t pass_limit_ = 0;
  // The device's largest storage block (or LFD_GL_LIMITS' lower one), read once at construction:
  // a GL query a frame would be a round trip on some drivers.
  size_t device_pass_limit_ = 0;
  int passes_ = 0;
};

}  // namespace lfd::gpu
