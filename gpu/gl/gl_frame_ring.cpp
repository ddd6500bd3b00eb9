#include "gpu/gl/gl_frame_ring.hpp"

#include <algorithm>
#include <cstring>
#include <limits>

namespace lfd::gpu {

double GlFrameReadout::seconds(size_t a, size_t b) const {
  return stamps_ns[b] > stamps_ns[a] ? double(stamps_ns[b] - stamps_ns[a]) * 1e-9 : 0.0;
}

GlFrameRing::GlFrameRing(size_t stamps, size_t readback_bytes, int max_slots)
    : stamps_(stamps), readback_bytes_(readback_bytes), max_slots_(std::max(max_slots, 2)) {
  if (readback_bytes_ > 0) readback_ = MappedReadBuffer(readback_bytes_ * size_t(max_slots_));
}

GlFrameRing::~GlFrameRing() {
  for (Slot& slot : slots_) drop_fence(slot);
}

void GlFrameRing::drop_fence(Slot& slot) {
  if (slot.fence) glDeleteSync(slot.fence);
  slot.fence = nullptr;
}

bool GlFrameRing::signalled(Slot& slot) const {
  if (!slot.fence) return false;
  const GLenum status = glClientWaitSync(slot.fence, 0, 0);  // a poll: timeout 0 never waits
  return status == GL_ALREADY_SIGNALED || status == GL_CONDITION_SATISFIED;
}

void GlFrameRing::begin_frame() {
  ++frames_;
  current_.reset();
  // A slot is free when it has never been used or its frame is done (and read or superseded);
  // the newest ended frame's slot is kept for reading.
  for (size_t i = 0; i < slots_.size(); ++i) {
    if (newest_ && i == *newest_) continue;
    if (!slots_[i].fence || signalled(slots_[i])) {
      current_ = i;
      break;
    }
  }
  if (!current_ && slots_.size() < size_t(max_slots_)) {
    Slot slot;
    std::vector<GLuint> ids(stamps_);
    if (stamps_ > 0) glCreateQueries(GL_TIMESTAMP, GLsizei(stamps_), ids.data());
    for (GLuint id : ids) slot.queries.emplace_back(id);
    slots_.push_back(std::move(slot));
    current_ = slots_.size() - 1;
  }
  if (!current_) return;  // every slot in flight: this frame is not recorded
  drop_fence(slots_[*current_]);
  slots_[*current_].frame = frames_;
}

void GlFrameRing::stamp(size_t index) {
  if (current_ && index < stamps_) glQueryCounter(slots_[*current_].queries[index].id(), GL_TIMESTAMP);
}

void GlFrameRing::copy_back(GLuint buffer, size_t offset, size_t bytes, size_t at) {
  if (!current_ || at + bytes > readback_bytes_) return;
  glCopyNamedBufferSubData(buffer, readback_.id(), GLintptr(offset),
                           GLintptr(*current_ * readback_bytes_ + at), GLsizeiptr(bytes));
}

void GlFrameRing::end_frame() {
  if (!current_) return;
  slots_[*current_].fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  glFlush();  // so the fence (and the frame) reach the GPU without a later call
  newest_ = current_;
  current_.reset();
}

GlFrameReadout GlFrameRing::read(const Slot& slot, size_t index) const {
  GlFrameReadout out;
  out.frame = slot.frame;
  out.frames_late = frames_ - slot.frame;
  out.stamps_ns.assign(stamps_, 0);
  for (size_t i = 0; i < stamps_; ++i)
    glGetQueryObjectui64v(slot.queries[i].id(), GL_QUERY_RESULT_NO_WAIT, &out.stamps_ns[i]);
  if (readback_bytes_ > 0) {
    out.bytes.resize(readback_bytes_);
    std::memcpy(out.bytes.data(), readback_.data() + index * readback_bytes_, readback_bytes_);
  }
  return out;
}

std::optional<GlFrameReadout> GlFrameRing::newest_ready() {
  std::optional<size_t> best;
  for (size_t i = 0; i < slots_.size(); ++i) {
    Slot& slot = slots_[i];
    if (current_ && i == *current_) continue;
    if (best && slots_[*best].frame >= slot.frame) continue;
    if (!signalled(slot)) continue;
    // The fence says the frame is done; the queries say their results are there.
    GLuint available = GL_TRUE;
    if (stamps_ > 0) glGetQueryObjectuiv(slot.queries.back().id(), GL_QUERY_RESULT_AVAILABLE, &available);
    if (available) best = i;
  }
  if (!best) return std::nullopt;
  return read(slots_[*best], *best);
}

std::optional<GlFrameReadout> GlFrameRing::wait_newest() {
  if (!newest_) return std::nullopt;
  Slot& slot = slots_[*newest_];
  if (!slot.fence) return std::nullopt;
  glClientWaitSync(slot.fence, GL_SYNC_FLUSH_COMMANDS_BIT, std::numeric_limits<GLuint64>::max());
  return read(slot, *newest_);
}

}  // namespace lfd::gpu
