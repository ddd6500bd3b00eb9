#pragma once
// The generic half of a compute tile rasterizer (docs/gpu.md "The compute tile rasterizer";
// contract gpu/compute/shaders/tile_io.h): whatever is drawn (Gaussians, voxels) into whatever images
// (a quilt's views, G2LF's planes), the client's passes count and write (slot, item) keys, and
// this class does the rest on the GPU:
//   scan    each item's tile count into its first key: three passes (block sums, one group over
//           the block sums, the items), so the keys of item j come before item j + 1's
//   sort    GlRadixSort of the keys by slot (image * tiles_per_image + tile) over the bits the
//           slot count needs: stable, so inside a slot the items keep their order (the client
//           gives them front to back: the depth order of the reference's (tile | depth) keys)
//   ranges  each slot's run of sorted keys, and the list of non-empty slots with a
//           DispatchIndirectCommand of one work group each (dispatch_work), so empty (image,
//           tile) pairs cost nothing
// scan() reads the key total back (it sizes the key buffers and the sort); scan_to_capacity and
// sort_and_find_ranges_to_capacity read nothing back.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "gpu/gl/gl_objects.hpp"
#include "gpu/gl/gl_program.hpp"
#include "gpu/compute/gl_radix_sort.hpp"
#include "gpu/compute/shaders/tile_io.h"

namespace lfd::gpu {

// A client's key pass counts each item's keys, or writes them (tile_key_writer.glsl's EMIT).
enum class KeyStep { kCount, kEmit };
// What a client's images are: a quilt's views, or the sweeping planes (the shaders' PLANES).
enum class TileImages { kViews, kPlanes };
// What a view's alpha holds once composited over the background: 1 (a quilt) or the
// transmittance T (one view's image, for a caller that composites it further).
enum class TargetAlpha { kOpaque, kTransmittance };
// The defines of a client's key pass ("EMIT 0|1", "PLANES 0|1").
std::vector<std::string> key_pass_defines(KeyStep step, TileImages images);

// The names under which a client's program declares the key engine's buffers it reads or writes
// (docs/gpu.md "Binding points"): GlTileKeys::bind(program) binds those the program declares.
// At the points of tile_io.h: kTileCountsBinding, kTileKeysBinding ... kTileStateBinding.
Binding tile_counts(Access access);
Binding tile_keys(Access access);
Binding tile_values(Access access);
Binding tile_ranges(Access access);
Binding tile_work(Access access);
Binding tile_state(Access access);

class GlTileKeys {
 public:
  GlTileKeys();  // needs a current context; compiles the passes

  // The per-item counts the client's count pass writes, at least `items` long.
  Buffer& counts(size_t items);
  // Scans counts[0, items) in place into each item's first key; returns the key total (waits for
  // the GPU to get it) and grows the key buffers to it.
  uint32_t scan(uint32_t items);
  // Sorts the `keys` keys by slot (slots < `slots`) and finds every slot's range and the
  // non-empty slots.
  void sort_and_find_ranges(uint32_t keys, uint32_t slots);

  // The same two steps with nothing read back (docs/gpu.md "Memory and passes"): the key total
  // stays on the GPU (TileState::keys); the key buffers hold `capacity` keys, cleared to
  // 0xFFFFFFFF (no key), and the client's write pass writes only the keys below it; the sort
  // drops the unwritten ones in its first pass (its kept count stays on the GPU) and the ranges
  // pass reads min(total, capacity) from the state. A total over the capacity (copy_key_total
  // tells the client) leaves keys out: the client grows the capacity and draws again.
  void scan_to_capacity(uint32_t items, uint32_t capacity);
  void sort_and_find_ranges_to_capacity(uint32_t slots);
  uint32_t capacity() const { return capacity_; }
  // Copies the last scan's key total into word `word` of `buffer`, on the GPU.
  void copy_key_total(const Buffer& buffer, uint32_t word) const;

  // Binds, through the client's program, those of the keys, values, ranges, the work list and the
  // state that it declares (tile_keys() ... above; the counts the client binds itself, sized by
  // counts()).
  void bind(const Program& program) const;
  // One work group per non-empty slot (groups x + y * gl_NumWorkGroups.x index the work list;
  // those past state.work_count do nothing), dispatched through the client's program, which must
  // be in use: its bindings are checked first.
  void dispatch_work(const Program& program) const;
  // Writes words[dispatch_word..+2] = a DispatchIndirectCommand of words[count_word] groups in
  // `buffer` (bound at kTileStateBinding): the same spreading for a client's own lists.
  void write_dispatch(const Buffer& buffer, uint32_t count_word, uint32_t dispatch_word) const;

  Buffer& keys() { return keys_; }
  Buffer& values() { return values_; }
  // What the ranges pass leaves (read by the tests): per slot uvec2 (first key, end key), the
  // non-empty slots, and the TileState.
  const Buffer& ranges() const { return ranges_buffer_; }
  const Buffer& work() const { return work_; }
  const Buffer& state() const { return state_; }
  GlRadixSort& sorter() { return sort_; }  // for a client's own sorts (one set of scratch buffers)
  size_t bytes() const;

 private:
  Program blocks_, totals_, items_, ranges_, dispatch_;
  GlRadixSort sort_;
  // The scan's three passes; returns false for no items.
  bool run_scan(uint32_t items);
  // The ranges of the first `keys` sorted keys (count_from_state: of min(TileState::keys, keys)).
  void find_ranges(uint32_t keys, uint32_t slots, bool count_from_state);

  Buffer counts_, block_sums_, state_, keys_, values_, ranges_buffer_, work_;
  uint32_t capacity_ = 0;  // keys the last scan_to_capacity left room for
};

// Bits that hold slots 0 .. slots - 1 (at least 1).
int slot_bits(uint32_t slots);

}  // namespace lfd::gpu
