#include "rgbd/rgbd_quilt.hpp"

#include <algorithm>
#include <cmath>

#include "rgbd/rgbd_frame.hpp"
#include "rgbd/rgbd_view_model.hpp"
#include "util/error.hpp"

namespace lfd::rgbd {
namespace {

// The source position (in [0, 1) across the half, top-down) of tile coordinate t in [0, 1]
// along one axis: the crop centre 0.5 + crop/2 (in half widths; crop_pos_y is + up, so it
// moves the centre toward smaller top-down rows) and the zoom about it (docs/rgbd.md).
float source_coordinate(float t, double crop, double zoom) {
  return 0.5f + 0.5f * float(crop) + (t - 0.5f) / float(zoom);
}

// Linear interpolation weights and the two clamped texel indices of coordinate s in [0, 1)
// across n texels (pixel centres at (i + 0.5) / n).
struct Lerp {
  int i0, i1;
  float t;
};
Lerp lerp_texels(float s, int n) {
  const float p = s * float(n) - 0.5f;
  const float f = std::floor(p);
  return {std::clamp(int(f), 0, n - 1), std::clamp(int(f) + 1, 0, n - 1), p - f};
}

void resample_row(const ImageF& frame, const RgbdSplit& split, const RgbdOptions& o, int y,
                  RgbdSource& out) {
  const int nc = frame.channels;
  const float sv = source_coordinate((float(y) + 0.5f) / float(out.height), -o.crop_pos_y, o.zoom);
  for (int x = 0; x < out.width; ++x) {
    const float su = source_coordinate((float(x) + 0.5f) / float(out.width), o.crop_pos_x, o.zoom);
    float* c = &out.colour.at(x, y, 0);
    float& d = out.depth[size_t(y) * out.width + x];
    if (!(su >= 0.0f && su < 1.0f && sv >= 0.0f && sv < 1.0f)) {
      c[0] = c[1] = c[2] = 0.0f;  // zoomed or cropped out: black, far
      d = 0.0f;
      continue;
    }
    const Lerp lx = lerp_texels(su, split.colour.width), ly = lerp_texels(sv, split.colour.height);
    for (int ch = 0; ch < 3; ++ch) {
      const auto texel = [&](int xi, int yi) {
        return frame.at(split.colour.x + xi, split.colour.y + yi, std::min(ch, nc - 1));
      };
      const float top = texel(lx.i0, ly.i0) + (texel(lx.i1, ly.i0) - texel(lx.i0, ly.i0)) * lx.t;
      const float bot = texel(lx.i0, ly.i1) + (texel(lx.i1, ly.i1) - texel(lx.i0, ly.i1)) * lx.t;
      c[ch] = top + (bot - top) * ly.t;
    }
    const int dx = std::min(int(su * float(split.depth.width)), split.depth.width - 1);
    const int dy = std::min(int(sv * float(split.depth.height)), split.depth.height - 1);
    const auto depth_channel = [&](int ch) {
      return frame.at(split.depth.x + dx, split.depth.y + dy, std::min(ch, nc - 1));
    };
    d = decode_depth(depth_channel(0), depth_channel(1), depth_channel(2), o.chroma_depth,
                     o.depth_inversion);
    // depth_cutoff: what lies farther than the threshold is removed; it keeps its depth, so the
    // views' geometry (and which side fills a hole) is that of the frame (docs/rgbd.md).
    if (d < float(o.depth_cutoff)) c[0] = c[1] = c[2] = 0.0f;
  }
}

}  // namespace

RgbdSource resample_rgbd(const ImageF& frame, const RgbdOptions& options, int tile_width,
                         int tile_height) {
  if (frame.empty() || frame.channels < 1)
    throw_input_error("RGB-D frame: empty image");
  if (tile_width < 1 || tile_height < 1)
    throw_input_error("RGB-D quilt: tile {}x{} is empty", tile_width, tile_height);
  const RgbdSplit split = split_rgbd_frame(frame.width, frame.height, options.depth_loc);
  RgbdSource out;
  out.width = tile_width;
  out.height = tile_height;
  out.colour = ImageF(tile_width, tile_height, 3);
  out.depth.assign(size_t(tile_width) * tile_height, 0.0f);
#pragma omp parallel for schedule(static)
  for (int y = 0; y < tile_height; ++y) resample_row(frame, split, options, y, out);
  return out;
}

WarpedView warp_view(const RgbdSource& source, const RgbdOptions& options,
                     float shift_px_per_z_ratio) {
  WarpedView view;
  view.width = source.width;
  view.height = source.height;
  view.colour = ImageF(source.width, source.height, 3);
  view.depth.assign(size_t(source.width) * source.height, kHole);
  for (int y = 0; y < source.height; ++y) {
    for (int x = 0; x < source.width; ++x) {
      const float d = source.depth_at(x, y);
      const float shift = shift_px_per_z_ratio * relief_z_ratio(d, options);
      const float landed = std::floor(float(x) + 0.5f + shift);
      if (!(landed >= 0.0f && landed < float(source.width))) continue;
      const int t = int(landed);
      float& z = view.depth[size_t(y) * view.width + t];
      if (d <= z) continue;  // the z-test: a nearer pixel already landed here
      z = d;
      for (int ch = 0; ch < 3; ++ch) view.colour.at(t, y, ch) = source.colour.at(x, y, ch);
    }
  }
  return view;
}

size_t fill_holes(WarpedView& view) {
  std::vector<std::pair<size_t, float>> filled;  // (index, depth), applied after the search
  for (int y = 0; y < view.height; ++y) {
    for (int t = 0; t < view.width; ++t) {
      if (view.depth_at(t, y) != kHole) continue;
      int l = t - 1, r = t + 1;
      while (l >= 0 && view.depth_at(l, y) == kHole) --l;
      while (r < view.width && view.depth_at(r, y) == kHole) ++r;
      int from = -1;
      if (l >= 0 && r < view.width) from = view.depth_at(r, y) < view.depth_at(l, y) ? r : l;
      else if (l >= 0) from = l;
      else if (r < view.width) from = r;
      if (from < 0) continue;  // nothing landed on the whole row: it stays black
      for (int ch = 0; ch < 3; ++ch) view.colour.at(t, y, ch) = view.colour.at(from, y, ch);
      filled.emplace_back(size_t(y) * view.width + t, view.depth_at(from, y));
    }
  }
  for (const auto& [i, d] : filled) view.depth[i] = d;
  return filled.size();
}

ImageF render_rgbd_quilt(const ImageF& frame, const RgbdOptions& options,
                         const render::QuiltLayout& layout, double view_cone_deg) {
  options.check("RGB-D options");
  const render::QuiltGeometry geometry = rgbd_quilt_geometry(layout, view_cone_deg);
  const RgbdSource source = resample_rgbd(frame, options, layout.tile_width(), layout.tile_height());
  ImageF quilt(layout.width, layout.height, 3);
#pragma omp parallel for schedule(dynamic)
  for (int j = 0; j < layout.views; ++j) {
    WarpedView view =
        warp_view(source, options, view_shift_px_per_z_ratio(geometry, j, source.width));
    fill_holes(view);
    const int x0 = layout.tile_x(j), y0 = layout.tile_y_top_down(j);
    for (int y = 0; y < view.height; ++y)
      std::copy_n(view.colour.row(y), size_t(view.width) * 3, quilt.row(y0 + y) + size_t(x0) * 3);
  }
  return quilt;
}

}  // namespace lfd::rgbd
