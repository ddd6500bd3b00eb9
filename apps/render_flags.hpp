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
#include "lightfield/render_settings.hpp"
#include "lightfield/renderer_factory.hpp"
#include "lightfield/view_plan.hpp"
#include "scene/scene.hpp"

namespace lfd::apps {

// The command line: the render settings it fills (lightfield/render_settings.hpp says what each
// means, for both commands and Python's lfd.render_quilt) and what only a command has (files,
// the panel, the backend).
struct RenderFlags {
  lightfield::RenderSettings s;
  std::string scene_path, size_text, out, camera_path, background_text = "0,0,0";
  std::string panel_path, blend = "nearest", backend_name = "cpu";
  int view = -1;
  bool overscan = false;
  bool direct = false;  // --direct: the panel straight from the planes, no quilt
  DisplaySource display_source;
  CLI::Option* camera_option = nullptr;
};

constexpr auto kFlags = lightfield::SettingNames::kFlags;

// --scene, --method, the views, grid and size, the G2LF/V2LF plane options.
void add_scene_and_plane_options(CLI::App& app, RenderFlags& f);
// --camera, --focal-distance, --view-cone, the display (--calibration/--device), --panel with
// --blend and --overscan, --background, --backend, --raster. `panel_help` says what --panel writes.
void add_camera_and_display_options(CLI::App& app, RenderFlags& f, const std::string& panel_help);

// What the flags ask, checked before anything is read; the texts (size, background, camera file)
// parsed into the settings.
void check_output_flags(RenderFlags& f, const CLI::App& app);

// The display when one is given (--calibration or --device).
struct DisplayChoice {
  std::optional<display::Calibration> calibration;
  std::string path;
};
DisplayChoice choose_display(RenderFlags& f);

// The renderer the flags choose for a scene of `kind`: its options (lightfield::renderer_options)
// and the GL device (null on the CPU); --raster auto resolved (and said) on the device.
struct RendererChoice {
  lightfield::RendererOptions options;
  std::shared_ptr<lightfield::GlDevice> device;
};
RendererChoice choose_renderer(const RenderFlags& f, scene::SceneKind kind);

// Prints the display's quilt, and a notice when the views' aspect differs from it.
void print_display(const DisplayChoice& display, const lightfield::ViewPlan& plan);

}  // namespace lfd::apps
