#pragma once
// The sweeping planes composited along single rays of any camera offset (docs/rendering.md
// "Direct panel rendering"): the swizzle blend of render/swizzle_blend.hpp for one ray at a time,
// with the view offset continuous instead of one of V views. The direct panel pass
// (interlace/direct_panel.hpp) asks it for one colour channel per panel subpixel, in the
// direction that subpixel is seen from. The plane coordinate is Eq. (u_prime) through
// plane_coordinate_x_at / plane_coordinate_y (render/quilt_geometry.hpp), the sampling and the
// front-to-back blend those of the swizzle (nearest or bilinear, empty outside the plane, a ray
// stops below half an 8-bit step of transmittance).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "render/plane_row.hpp"
#include "render/plane_samples.hpp"
#include "render/quilt_geometry.hpp"
#include "render/sweeping_planes.hpp"
#include "render/swizzle_blend.hpp"

namespace lfd::render {

// One ray of a row: camera offset dx (QuiltGeometry::view_offset_at), horizontal base-camera NDC
// u, and the colour channel wanted (0 R, 1 G, 2 B). A row's rays come in order of u
// (non-decreasing), which lets a plane skip the rays that cannot reach its non-empty columns.
struct PlaneRay {
  float dx = 0, u_ndc = 0;
  int channel = 0;
};

class PlaneRays {
 public:
  // The planes must outlive this object. `kernel`: the sampling loop (render/plane_samples.hpp),
  // by default the fastest this CPU has; one it lacks throws.
  PlaneRays(const SweepingPlanes& planes, const QuiltGeometry& geometry, const ReferenceCamera& ref,
            PlaneFilter filter, const glm::vec3& background, SampleKernel kernel = sample_window_kernel());

  // The working memory of composite_row, kept by the caller across rows (one per thread) so a
  // row allocates nothing.
  struct Scratch {
    std::vector<uint32_t> ray;  // the rays grouped by offset bin, in order of u within a bin
    std::vector<float> dx, u, colour, trans;
    std::vector<int32_t> channel, channel_offset;  // channel_offset: channel x BlendedPlaneRow::stride
    std::vector<uint8_t> bin;  // per ray, in the order given
    std::vector<uint32_t> bin_begin;  // kOffsetBins + 1 starts
    std::vector<uint32_t> bin_end;    // per bin, the end of its unfinished rays
    std::vector<float> bin_dx_min, bin_dx_max;
    std::vector<int> bin_active;
    BlendedPlaneRow row;
  };

  // The composited channel of every ray of one row of base-camera NDC v_ndc_top_down
  // ((2 y + 1) / H - 1 for view row y, rows top-down as the planes): out[i] for rays[i]. The
  // largest |dx| of the rays is `max_abs_dx` (the view cone's edge).
  void composite_row(float v_ndc_top_down, float max_abs_dx, const std::vector<PlaneRay>& rays,
                     std::vector<float>& out, Scratch& scratch) const;
  void composite_row(float v_ndc_top_down, float max_abs_dx, const std::vector<PlaneRay>& rays,
                     std::vector<float>& out) const {
    Scratch scratch;
    composite_row(v_ndc_top_down, max_abs_dx, rays, out, scratch);
  }

  // One ray through every plane, the sampling and the blend spelled out as the swizzle does them
  // (render/swizzle_blend.cpp): the definition composite_row computes faster, for the tests.
  float composite_ray(const PlaneRay& ray, float v_ndc_top_down) const;

 private:
  // Per plane: Eq. (u_prime) as u' = dx parallax + u scale_x, v' = v scale_y.
  struct PlaneMap {
    float parallax, scale_x, scale_y;
  };
  // The plane rows a row of rays reads and the vertical weight.
  struct PlaneRows {
    int row0, row1;
    float fy;
  };
  PlaneRows plane_rows(int k, float v_ndc) const;
  void bin_rays(const std::vector<PlaneRay>& rays, float max_abs_dx, Scratch& s) const;
  // `out`: where rays finished early (compact_bin) put their value.
  void composite_plane(int k, Scratch& s, int& active, float* out) const;
  // Finishes the bin's stopped rays into `out` and closes up the rest, in order.
  void compact_bin(int b, Scratch& s, float* out) const;
  // A ray's value after its last plane: its colour over the background.
  float finished(const Scratch& s, size_t slot) const {
    return s.colour[slot] + s.trans[slot] * background_[s.channel[slot]];
  }

  const SweepingPlanes& planes_;
  std::vector<PlaneMap> maps_;
  PlaneFilter filter_;
  glm::vec3 background_;
  SampleKernel kernel_;
};

}  // namespace lfd::render
