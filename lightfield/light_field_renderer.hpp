#pragma once
// One interface for every light-field renderer: CPU or GL, Gaussians or voxels, every view
// alone or the sweeping planes (G2LF, V2LF). `lfd render`, the demo, the viewer and both
// benchmarks render through it; lightfield/renderer_factory.hpp makes the one the options ask
// for. A quilt call returns when the quilt is complete (a GL renderer waits for the GPU), so the
// wall time around it is the frame time; the quilt is read back only in read_quilt, so a GPU
// frame is timed without its read-back (docs/performance.md).
#include <cstddef>
#include <string>

#include "display/lens_model.hpp"
#include "scene/scene.hpp"
#include "lightfield/renderer_options.hpp"
#include "render/quilt_geometry.hpp"
#include "render/quilt_layout.hpp"
#include "util/image.hpp"

namespace lfd::lightfield {

// A quilt's figures. Per view: zeros (GL with gl.gpu_timers: seconds_raster). Sweeping planes:
// the planes and their bytes (GL G2LF: the N_chunk layers allocated; the used count needs a
// read-back), the primitives binned (Gaussians in the reference frustum, voxels in the chunks,
// split children included; GL G2LF only with gpu_timers) and the stage times when known.
struct QuiltStats {
  int planes = 0;
  size_t plane_bytes = 0;
  size_t binned = 0;
  size_t voxels_split = 0;
  double seconds_binning = 0, seconds_planes = 0, seconds_swizzle = 0;
  double seconds_raster = 0;  // per view: preprocess + sort + raster, summed over the views
};

// What a direct panel frame is asked for beyond the display's lens: the interlacer's options
// that apply to it (view blending does not: every subpixel shows its own view).
struct PanelOptions {
  bool overscan = false;      // interlace::InterlaceOptions::overscan
  bool invert_views = false;  // interlace::InterlaceOptions::invert_views
};

class LightFieldRenderer {
 public:
  virtual ~LightFieldRenderer() = default;

  // "cpu", "gl": the backend's name.
  virtual std::string name() const = 0;
  // What it runs on, for reports ("CPU, 2 OpenMP threads", the GL renderer string).
  virtual std::string device() const = 0;
  // Frames a benchmark times unless told otherwise (CPU 3, GPU 10).
  virtual int default_runs() const = 0;
  virtual const RendererOptions& options() const = 0;
  // The options of the following frames; the backend and method must stay (std::logic_error).
  virtual void set_options(const RendererOptions& options) = 0;

  // The scene of the following frames, of the renderer's kind (std::logic_error otherwise);
  // untimed (a GL renderer uploads it here, unless its device holds it already). The scene
  // outlives the frames.
  virtual void set_scene(const scene::Scene& scene) = 0;

  // One whole quilt (checks the options against `geometry` first: InputError).
  virtual QuiltStats render_quilt(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout) = 0;
  // One view rendered alone through its off-axis camera (the sweeping methods render whole
  // quilts only, so theirs is the per-view image too): RGB, top row first.
  virtual ImageF render_view(const render::QuiltGeometry& geometry, int view) = 0;
  // The last quilt (RGB floats, top row first), read back if it lives elsewhere.
  virtual const ImageF& read_quilt() = 0;
  // The last quilt handed over to the caller, which keeps it (a benchmark's ground truth): a CPU
  // renderer moves it out rather than holding a second copy beside the caller's, which would
  // show in the process's peak memory; elsewhere a copy of read_quilt().
  virtual ImageF take_quilt() { return read_quilt(); }

  // Direct panel rendering (docs/rendering.md "Direct panel rendering"): the panel of `lens`'s
  // display straight from the sweeping planes, every subpixel at its own view angle, no quilt
  // (QuiltStats::seconds_swizzle is the direct pass). Sweeping-plane renderers only: the others
  // throw InputError. Checks the options against `geometry` first.
  virtual QuiltStats render_panel(const render::QuiltGeometry& geometry, const display::LensModel& lens,
                                  const PanelOptions& options);
  // The last panel (screenW x screenH RGB floats, top row first), read back if it lives elsewhere.
  virtual const ImageF& read_panel();

  // Peak memory since the last reset: what it measures is `memory_kind()` ("process RSS",
  // "GPU memory (...)").
  virtual std::string memory_kind() const = 0;
  virtual void reset_peak_memory() = 0;
  virtual size_t peak_memory_bytes() const = 0;
};

}  // namespace lfd::lightfield
