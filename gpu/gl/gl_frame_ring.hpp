#pragma once
// What a frame leaves for the CPU to read (GPU timestamps, a few bytes of a GPU-written buffer)
// without making the CPU wait: a ring of slots, one per frame in flight, each with its
// GL_TIMESTAMP queries, a region of a persistently mapped buffer the GPU copies into, and a
// fence after the frame. A slot is read only once its fence has signalled (glClientWaitSync with
// timeout 0) and its last query reports GL_QUERY_RESULT_AVAILABLE; the queries are then read
// with GL_QUERY_RESULT_NO_WAIT, so no call in the frame loop waits (docs/gpu.md, "A frame that
// never waits"). Benchmarks, which finish every frame anyway, read the frame just ended with
// `wait_newest`.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <epoxy/gl.h>

#include "gpu/gl/gl_mapped_buffer.hpp"
#include "gpu/gl/gl_objects.hpp"

namespace lfd::gpu {

// How a renderer's stage timers are read: at the end of the frame, waiting for it (benchmarks,
// which finish every frame anyway), or late, from the newest frame the GPU has finished, never
// waiting (the viewer).
enum class TimerReads { kWait, kLate };

// What one frame left: its timestamps (ns; index as given to stamp) and copied bytes.
struct GlFrameReadout {
  std::vector<uint64_t> stamps_ns;
  std::vector<std::byte> bytes;
  uint64_t frame = 0;       // the number of the frame (begin_frame calls before it)
  uint64_t frames_late = 0;  // frames begun since it, when it was read
  // Seconds between stamps a and b (0 if b is not after a).
  double seconds(size_t a, size_t b) const;
};

class GlFrameRing {
 public:
  // Slots are made as frames are in flight, at most `max_slots`; a frame that would reuse a slot
  // still in flight is not recorded (its stamps and copies are skipped) rather than waited for.
  GlFrameRing(size_t stamps, size_t readback_bytes, int max_slots = 6);
  GlFrameRing(GlFrameRing&&) noexcept = default;
  GlFrameRing& operator=(GlFrameRing&&) = delete;  // would drop the fences of the old slots
  ~GlFrameRing();

  size_t stamps() const { return stamps_; }
  size_t readback_bytes() const { return readback_bytes_; }
  // Starts a frame: picks a free slot (polling, never waiting), or none.
  void begin_frame();
  // glQueryCounter(GL_TIMESTAMP) for stamp `index` of this frame (nothing if it has no slot).
  void stamp(size_t index);
  // A GPU copy of `bytes` of `buffer` at `offset` into this frame's readback at `at`.
  void copy_back(GLuint buffer, size_t offset, size_t bytes, size_t at);
  // Ends the frame: its fence.
  void end_frame();

  // The newest ended frame whose results are there now, never waiting; nullopt if none is (yet).
  std::optional<GlFrameReadout> newest_ready();
  // The frame just ended, waiting for it (benchmarks and tests; never in an interactive frame).
  std::optional<GlFrameReadout> wait_newest();

 private:
  struct Slot {
    std::vector<GlName<delete_query>> queries;
    GLsync fence = nullptr;
    uint64_t frame = 0;
  };
  bool signalled(Slot& slot) const;  // polls the fence (timeout 0)
  GlFrameReadout read(const Slot& slot, size_t index) const;
  void drop_fence(Slot& slot);

  size_t stamps_ = 0, readback_bytes_ = 0;
  int max_slots_ = 0;
  std::vector<Slot> slots_;
  MappedReadBuffer readback_;  // max_slots_ regions of readback_bytes_
  std::optional<size_t> current_;  // this frame's slot
  std::optional<size_t> newest_;   // the last ended frame's slot
  uint64_t frames_ = 0;
};

}  // namespace lfd::gpu
