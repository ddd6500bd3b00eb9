#pragma once
// The flags that choose what a light field is rendered as: its scene, views, grid, size, camera,
// display, method, planes and backend. `lfd render` and `lfd record` both take them (one
// definition of each flag); each command adds its own outputs.
#include <memory>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "apps/cli.hpp"
#include "lightfield/gl_device.hpp"
#include "lightfield/renderer_factory.hpp"
#include "lightfield/view_plan.hpp"
#include "render/g2lf.hpp"
#include "scene/scene.hpp"

namespace lfd::apps {

// The command line, as given.
struct RenderFlags {
  std::string scene_path, method = "g2lf", size_text, out, camera_path;
  std::string filter, precision = "u8", binning = "mixed", background_text = "0,0,0";
  std::string panel_path, blend = "nearest", backend_name = "cpu";
  std::string raster = "hardware";  // --raster (docs/gpu.md)
  std::optional<int> views_opt, cols_opt, rows_opt;
  int view = -1;
  bool overscan = false;
  bool direct = false;  // --direct: the panel straight from the planes, no quilt
  float orbit_deg = 0.0f, focal_distance = 0.0f;
  std::optional<float> view_cone_opt;
  render::G2lfOptions g2lf;
  int split_levels = 0;
  bool no_plane_lowpass = false;
  DisplaySource display_source;
  glm::vec3 background{0.0f};  // --background, parsed
  CLI::Option* camera_option = nullptr;
};

// --scene, --method, the views, grid and size, the G2LF/V2LF plane options.
void add_scene_and_plane_options(CLI::App& app, RenderFlags& f);
// --camera, --focal-distance, --view-cone, the display (--calibration/--device), --panel with
// --blend and --overscan, --background, --backend, --raster. `panel_help` says what --panel writes.
void add_camera_and_display_options(CLI::App& app, RenderFlags& f, const std::string& panel_help);

// What the flags ask, checked before anything is read (the background parsed).
void check_output_flags(RenderFlags& f);

// The display when one is given (--calibration or --device).
struct DisplayChoice {
  std::optional<display::Calibration> calibration;
  std::string path;
};
DisplayChoice choose_display(RenderFlags& f);

// The renderer the flags choose for a scene of `kind`: its options and the GL device (null on
// the CPU). InputError naming the flag for a method or option of the other kind of scene.
struct RendererChoice {
  lightfield::RendererOptions options;
  std::shared_ptr<lightfield::GlDevice> device;
};
RendererChoice choose_renderer(const RenderFlags& f, const CLI::App& app, scene::SceneKind kind);

// The flags' request of the view plan (lightfield/view_plan.hpp decides what is not given).
lightfield::ViewRequest view_request(const RenderFlags& f, const DisplayChoice& display);
// The plan of `request` (view_request's, perhaps with a camera of the caller's), with the grid's
// refusal named by the flags that chose it.
lightfield::ViewPlan plan_render_views(const RenderFlags& f, const lightfield::ViewRequest& request,
                                       const scene::Scene& scene);
// Prints the display's quilt, and a notice when the views' aspect differs from it.
void print_display(const DisplayChoice& display, const lightfield::ViewPlan& plan);

}  // namespace lfd::apps
