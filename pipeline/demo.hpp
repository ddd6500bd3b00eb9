#pragma once
// `lfd demo`: the main job end to end on embedded defaults. A simulated display unit (a real
// unit's factory calibration plus a smooth lens-array warp only its own calibration knows) is
// calibrated from simulated photographs of the calibration patterns; the bundled Gaussian
// scene rendered with G2LF and a numbered test quilt are interlaced with the recovered
// calibration, photographed by the simulator from three positions, validated against the true
// calibration, the factory file and a 0.01-degree slant error, and a report (HTML with images
// and plots) is written.
#include <filesystem>
#include <string>

#include "gpu/gl/raster_path.hpp"

namespace lfd::pipeline {

struct DemoOptions {
  std::filesystem::path out_dir = "out/demo";
  std::filesystem::path unit_calibration;  // default: data/calibrations/LKG-2K-04409.visual.json
  std::filesystem::path scene;             // default: data/scenes/playbot.sog (a real scene, CC-BY-4.0)
  double warp_amplitude_periods = 0.3;     // the simulated unit's lens-array warp (max |w|)
  int tile_width = 384;                    // quilt tile width in pixels (height from the aspect)
  int validation_points = 600;             // panel points per validation profile
  int capture_width = 1280;
  bool verbose = true;
  // Render and interlace on the GPU when an OpenGL context can be made (headless EGL), else on
  // the CPU with a notice; false: the CPU always.
  bool use_gpu = true;
  // How the GPU draws the scene's Gaussians (`lfd demo --raster`; auto: measured, docs/gpu.md).
  gpu::RasterPath raster = gpu::RasterPath::kHardware;
};

// Runs the demo; returns the path of the report's index.html.
std::filesystem::path run_demo(const DemoOptions& options);

}  // namespace lfd::pipeline
