#pragma once
// The sweeping-plane skeleton on the GPU, shared by GlG2lfRenderer (gpu/splats/gl_g2lf.hpp) and
// GlV2lfRenderer (gpu/voxels/gl_v2lf.hpp): the GL twin of render/sweeping_plane_pipeline.hpp. It keeps
// the plane array between frames and runs a frame: the reference camera
// (render::reference_camera), the renderer's stages (GlSweepingPlaneStages), the quilt cleared
// outside the tiles and the swizzle (GlSwizzle), with GL_TIMESTAMP queries between the stages
// when the frame is timed (llvmpipe's GL_TIME_ELAPSED reads 0 around compute).
#include <cstddef>
#include <functional>
#include <optional>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "gpu/gl/gl_frame_ring.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/planes/gl_planes.hpp"
#include "gpu/planes/gl_swizzle.hpp"
#include "render/g2lf.hpp"
#include "render/quilt_geometry.hpp"
#include "render/quilt_layout.hpp"

namespace lfd::gpu {

// The stages a renderer supplies for one frame; each enqueues GPU work (or works on the CPU and
// uploads).
struct GlSweepingPlaneStages {
  // Before the binning, timed with the planes (G2LF's preprocess); may be empty.
  std::function<void(const render::ReferenceCamera&)> prepare;
  // Alg. 1 lines 1-3: the primitives binned, the plane table of `planes` written.
  std::function<void(const render::ReferenceCamera&, GlPlanes& planes)> bin;
  // Alg. 1 lines 4-5: every plane's layer of `planes` drawn.
  std::function<void(const render::ReferenceCamera&, GlPlanes& planes)> draw_planes;
};

// GPU seconds of a timed frame's stages; planes = prepare + draw_planes.
struct GlSweepingPlaneSeconds {
  double binning = 0, planes = 0, swizzle = 0;
};

// What a timed frame leaves: its stage times and its plane table's header (plane and binned
// counts), copied on the GPU into a mapped buffer (gpu/gl/gl_frame_ring.hpp).
struct GlSweepingPlaneReadout {
  GlSweepingPlaneSeconds seconds;
  PlaneTableHeader header;
  uint64_t frames_late = 0;  // 0: the frame just rendered
};

class GlSweepingPlanes {
 public:
  // True when the plane array is allocated with this format, layer count and size.
  bool has_planes(PlaneFormat format, int max_planes, int width, int height) const;
  // A new plane array (the old one freed first: a lower peak).
  void allocate_planes(PlaneFormat format, int max_planes, int width, int height);
  // All of the swizzle's options (its views per invocation, factor table, hardware bilinear).
  void set_swizzle(const SwizzleOptions& options);

  // One frame into `quilt` (checked by the caller: check_quilt_target): the reference camera of
  // `options`, the stages, the quilt cleared to 0 outside the tiles as the CPU's, the swizzle
  // with options.filter over `background`. `frame` names the frame in GL errors.
  void render_quilt(const GlSweepingPlaneStages& stages, const render::QuiltGeometry& geometry,
                    const render::QuiltLayout& layout, const render::G2lfOptions& options,
                    const glm::vec3& background, const Texture& quilt, bool timed, const char* frame);

  // The same frame with the planes handed to `pass` instead of the swizzle (the direct panel
  // pass, gpu/panel/gl_direct_panel.hpp: no quilt); its GPU time is the swizzle's.
  using PlanePass = std::function<void(const GlPlanes&, const render::ReferenceCamera&)>;
  void render_planes(const GlSweepingPlaneStages& stages, const render::QuiltGeometry& geometry,
                     const render::G2lfOptions& options, const PlanePass& pass, bool timed, const char* frame);

  // The figures of the frame just rendered (kWait: waits for it) or of the newest timed frame
  // the GPU has finished (kLate: never waits; nullopt while none has). Only timed frames count.
  std::optional<GlSweepingPlaneReadout> readout(TimerReads reads);
  const GlPlanes& planes() const { return planes_; }
  size_t bytes() const;  // the plane array and its table

 private:
  enum Stamp { kStart, kPrepared, kBinned, kDrawn, kSwizzled, kStamps };
  void stamp(Stamp at);

  GlPlanes planes_;
  GlSwizzle swizzle_;
  std::optional<GlFrameRing> ring_;  // made by the first timed frame
  bool timed_ = false;
};

}  // namespace lfd::gpu
