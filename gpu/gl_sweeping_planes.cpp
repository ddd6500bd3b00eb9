#include "gpu/gl_sweeping_planes.hpp"

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

size_t GlSweepingPlanes::bytes() const { return planes_.texels.bytes() + planes_.table.buffer.bytes(); }

void GlSweepingPlanes::stamp(Stamp at) {
  if (!timed_) return;
  while (stamps_.size() < kStamps) {
    GLuint id = 0;
    glGenQueries(1, &id);
    stamps_.emplace_back(id);
  }
  glQueryCounter(stamps_[at].id(), GL_TIMESTAMP);
}

double GlSweepingPlanes::seconds_between(Stamp a, Stamp b) const {
  GLuint64 ns_a = 0, ns_b = 0;
  glGetQueryObjectui64v(stamps_[a].id(), GL_QUERY_RESULT, &ns_a);
  glGetQueryObjectui64v(stamps_[b].id(), GL_QUERY_RESULT, &ns_b);
  return double(ns_b - ns_a) * 1e-9;
}

GlSweepingPlaneSeconds GlSweepingPlanes::seconds() const {
  GlSweepingPlaneSeconds s;
  s.planes = seconds_between(kStart, kPrepared) + seconds_between(kBinned, kDrawn);
  s.binning = seconds_between(kPrepared, kBinned);
  s.swizzle = seconds_between(kDrawn, kSwizzled);
  return s;
}

void GlSweepingPlanes::render_planes(const GlSweepingPlaneStages& stages, const render::QuiltGeometry& geometry,
                                     const render::G2lfOptions& options, const PlanePass& pass, bool timed,
                                     const char* frame) {
  const render::ReferenceCamera ref = render::reference_camera(options, geometry);
  timed_ = timed;
  stamp(kStart);
  if (stages.prepare) stages.prepare(ref);
  stamp(kPrepared);
  stages.bin(ref, planes_);
  stamp(kBinned);
  stages.draw_planes(ref, planes_);
  stamp(kDrawn);
  pass(planes_, ref);
  stamp(kSwizzled);
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
