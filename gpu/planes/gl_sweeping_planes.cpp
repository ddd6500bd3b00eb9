#include "gpu/planes/gl_sweeping_planes.hpp"

#include <cstring>

#include "render/sweeping_plane_pipeline.hpp"

namespace lfd::gpu {

bool GlSweepingPlanes::has_planes(PlaneFormat format, int max_planes, int width, int height) const {
  return planes_.texels.id() && planes_.format == format && planes_.max_planes == max_planes &&
         planes_.width == width && planes_.height == height;
}

void GlSweepingPlanes::allocate_planes(PlaneFormat format, int max_planes, int width, int height) {
  planes_ = GlPlanes();
  planes_ = GlPlanes(format, max_planes, width, height);
}

void GlSweepingPlanes::set_swizzle(const SwizzleOptions& options) {
  if (!(swizzle_.options() == options)) swizzle_ = GlSwizzle(options);
}

size_t GlSweepingPlanes::bytes() const { return planes_.texels.bytes() + planes_.table.buffer.bytes(); }

void GlSweepingPlanes::stamp(Stamp at) {
  if (timed_) ring_->stamp(at);
}

std::optional<GlSweepingPlaneReadout> GlSweepingPlanes::readout(TimerReads reads) {
  if (!ring_) return std::nullopt;
  const std::optional<GlFrameReadout> frame = reads == TimerReads::kWait ? ring_->wait_newest() : ring_->newest_ready();
  if (!frame) return std::nullopt;
  GlSweepingPlaneReadout r;
  r.seconds.planes = frame->seconds(kStart, kPrepared) + frame->seconds(kBinned, kDrawn);
  r.seconds.binning = frame->seconds(kPrepared, kBinned);
  r.seconds.swizzle = frame->seconds(kDrawn, kSwizzled);
  std::memcpy(&r.header, frame->bytes.data(), sizeof(PlaneTableHeader));
  r.frames_late = frame->frames_late;
  return r;
}

void GlSweepingPlanes::render_planes(const GlSweepingPlaneStages& stages, const render::QuiltGeometry& geometry,
                                     const render::G2lfOptions& options, const PlanePass& pass, bool timed,
                                     const char* frame) {
  const render::ReferenceCamera ref = render::reference_camera(options, geometry);
  timed_ = timed;
  if (timed_) {
    if (!ring_) ring_.emplace(kStamps, sizeof(PlaneTableHeader));
    ring_->begin_frame();
  }
  stamp(kStart);
  if (stages.prepare) stages.prepare(ref);
  stamp(kPrepared);
  stages.bin(ref, planes_);
  stamp(kBinned);
  stages.draw_planes(ref, planes_);
  stamp(kDrawn);
  pass(planes_, ref);
  stamp(kSwizzled);
  if (timed_) {
    // The header (plane and binned counts) goes to the CPU through a GPU copy read frames
    // later, never through a read-back that waits (docs/gpu.md, "A frame that never waits").
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    ring_->copy_back(planes_.table.buffer.id(), 0, sizeof(PlaneTableHeader), 0);
    ring_->end_frame();
  }
  check_gl(frame);
}

void GlSweepingPlanes::render_quilt(const GlSweepingPlaneStages& stages, const render::QuiltGeometry& geometry,
                                    const render::QuiltLayout& layout, const render::G2lfOptions& options,
                                    const glm::vec3& background, const Texture& quilt, bool timed,
                                    const char* frame) {
  render_planes(
      stages, geometry, options,
      [&](const GlPlanes& planes, const render::ReferenceCamera& ref) {
        const float outside[4] = {0.0f, 0.0f, 0.0f, 1.0f};  // outside the tiles: 0, as the CPU's
        glClearTexImage(quilt.id(), 0, GL_RGBA, GL_FLOAT, outside);
        swizzle_.run(planes, geometry, ref, layout, options.filter, background, quilt);
      },
      timed, frame);
}

}  // namespace lfd::gpu
