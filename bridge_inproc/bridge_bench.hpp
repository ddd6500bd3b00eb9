#pragma once
// How long draw_interop_quilt_texture_gl holds its caller (docs/bridge-inproc.md "Speed"), measured
// as a client measures it: the library loaded with dlopen like the vendor's Controller, the caller a
// headless EGL context of its own with a quilt texture, the draws into a window of the display
// (offscreen unless asked: no X needed) while the library's thread interlaces the frames before.
#include <filesystem>
#include <string>
#include <vector>

namespace lfd::bridge {

struct BridgeBenchOptions {
  std::filesystem::path library;      // libbridge_inproc.so
  std::filesystem::path calibration;  // the display
  std::vector<int> quilt_sizes = {2048, 3360, 4096};  // square quilts, 8x6 views
  int warmup = 5;
  int runs = 30;
  bool on_screen = false;  // instance_window_gl instead of the offscreen window (needs X)
};

struct BridgeBenchRow {
  int quilt_size = 0;
  std::vector<double> hold_s;   // each draw_interop_quilt_texture_gl call
  std::vector<double> frame_s;  // a draw and the panel read back after it (the frame done)
};

// InputError when the library cannot be loaded, a call fails or no GL context can be made.
std::vector<BridgeBenchRow> run_bridge_bench(const BridgeBenchOptions& options);

}  // namespace lfd::bridge
