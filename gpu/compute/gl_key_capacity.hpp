#pragma once
// How a tile rasterizer recovers a pass whose keys outgrow their buffers, the same for Gaussians
// and voxels (docs/gpu.md "Memory and passes"): the key buffers hold a capacity kept from frame to
// frame (at first a key an item); each pass scans and writes its keys to that capacity
// (GlTileKeys::scan_to_capacity: keys past it are left out) and copies its key total, on the GPU,
// into its word of a frame's buffer; after the whole frame is issued the client reads the totals
// once (the one wait), grows the capacity to a quarter over the largest and draws again the
// passes whose keys did not fit (the same keys then fit: once is enough). Nothing is read back
// inside a frame.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "gpu/compute/gl_tile_keys.hpp"
#include "gpu/gl/gl_objects.hpp"

namespace lfd::gpu {

class GlKeyCapacity {
 public:
  // The capacity for a pass of `items` items: the one kept, or a key an item before any.
  uint32_t for_pass(uint32_t items);
  uint32_t keys() const { return capacity_; }
  // Starts from another capacity (tests).
  void set_keys(uint32_t keys) { capacity_ = keys; }

  // Copies the last scan's key total of `tiles` into word `pass` of the frame's totals; the
  // buffer grows as passes come, keeping the words already copied.
  void record(const GlTileKeys& tiles, uint32_t pass);
  // The frame's one read (waits for the GPU): the first `passes` totals, the passes whose keys
  // outgrew the capacity (then grown past them, to at most `largest`) and the frame's sum.
  struct FrameKeys {
    std::vector<uint32_t> totals, overflowed;
    uint64_t sum = 0;
  };
  FrameKeys read_frame(uint32_t passes, uint32_t largest = UINT32_MAX);

  size_t bytes() const { return totals_.bytes(); }

 private:
  Buffer totals_;
  uint32_t capacity_ = 0;
};

}  // namespace lfd::gpu
