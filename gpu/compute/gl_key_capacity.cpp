#include "gpu/compute/gl_key_capacity.hpp"

#include <algorithm>

namespace lfd::gpu {

uint32_t GlKeyCapacity::for_pass(uint32_t items) {
  if (capacity_ == 0) capacity_ = std::max<uint32_t>(items, 1);
  return capacity_;
}

void GlKeyCapacity::record(const GlTileKeys& tiles, uint32_t pass) {
  const size_t needed = (size_t(pass) + 1) * 4;
  if (totals_.bytes() < needed) {  // grow keeping the passes already copied (ensure would drop them)
    Buffer grown(std::max<size_t>(needed, totals_.bytes() * 2));
    if (totals_.bytes() > 0) {
      glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
      glCopyNamedBufferSubData(totals_.id(), grown.id(), 0, 0, GLsizeiptr(totals_.bytes()));
    }
    totals_ = std::move(grown);
  }
  tiles.copy_key_total(totals_, pass);
}

GlKeyCapacity::FrameKeys GlKeyCapacity::read_frame(uint32_t passes, uint32_t largest) {
  FrameKeys frame;
  if (passes == 0) return frame;
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  frame.totals = totals_.download_as<uint32_t>(passes);
  uint64_t most = 0;
  for (uint32_t p = 0; p < passes; ++p) {
    frame.sum += frame.totals[p];
    most = std::max<uint64_t>(most, frame.totals[p]);
    if (frame.totals[p] > capacity_) frame.overflowed.push_back(p);
  }
  if (!frame.overflowed.empty())
    capacity_ = uint32_t(std::min<uint64_t>({most + most / 4 + 1024, largest, UINT32_MAX}));
  return frame;
}

}  // namespace lfd::gpu
