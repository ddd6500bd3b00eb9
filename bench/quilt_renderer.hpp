#pragma once
// The backend hook of `lfd bench render`: one quilt renderer per backend, each able to render
// the per-view quilt (the ground truth) and G2LF. The benchmark (bench/render_benchmark.hpp)
// times the render calls and reads quilts back only outside the timed calls, so a GPU backend
// is timed without its read-back. The CPU backend is bench/cpu_quilt_renderer.hpp; a GL one
// implements the same five calls on gpu/.
#include <cstddef>
#include <string>

#include "render/g2lf.hpp"
#include "render/gaussian_scene.hpp"
#include "render/quilt_geometry.hpp"
#include "render/quilt_layout.hpp"
#include "util/image.hpp"

namespace lfd::bench {

class QuiltRenderer {
 public:
  virtual ~QuiltRenderer() = default;

  // "cpu", "gl": the --backend name.
  virtual std::string name() const = 0;
  // What it runs on, for the report ("2 OpenMP threads", the GL renderer string).
  virtual std::string device() const = 0;
  // Frames timed per configuration unless the user says otherwise (CPU 3, GPU 10 and more).
  virtual int default_runs() const = 0;

  // The scene of the following frames; untimed (a GPU backend uploads it here). The scene
  // outlives the frames.
  virtual void set_scene(const render::GaussianScene& scene) = 0;

  // One whole quilt; returns when the frame is complete (a GPU backend waits for the GPU), so
  // the wall time around the call is the frame time.
  virtual void render_per_view(const render::QuiltGeometry& geometry,
                               const render::QuiltLayout& layout) = 0;
  // Same for G2LF; returns the frame's figures (planes, plane bytes; stage times if known).
  virtual render::G2lfStats render_g2lf(const render::QuiltGeometry& geometry,
                                        const render::QuiltLayout& layout,
                                        const render::G2lfOptions& options) = 0;

  // The last frame's quilt (RGB floats, top row first), read back if it lives elsewhere.
  virtual const ImageF& read_quilt() = 0;

  // Peak memory since the last reset: what it measures is `memory_kind()` ("process RSS",
  // "GPU memory").
  virtual std::string memory_kind() const = 0;
  virtual void reset_peak_memory() = 0;
  virtual size_t peak_memory_bytes() const = 0;
};

}  // namespace lfd::bench
