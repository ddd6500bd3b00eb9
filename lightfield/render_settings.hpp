#pragma once
// What a caller asks a render for, as `lfd render`'s and `lfd record`'s flags and Python's
// lfd.render_quilt keyword arguments name it (docs/python.md): the method, the views (count, grid,
// size, cone, camera, orbit, focal distance), the planes' options, the GL raster path and the
// frame of a moving scene. One mapping onto the renderer's options
// (renderer_factory.hpp) and the view plan (view_plan.hpp) serves both, so the command line and
// Python render the same quilt from the same settings.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include <glm/glm.hpp>

#include "display/calibration_file.hpp"
#include "display/display_quilt.hpp"
#include "lightfield/renderer_options.hpp"
#include "lightfield/view_plan.hpp"
#include "render/camera_json.hpp"
#include "render/g2lf.hpp"
#include "scene/scene.hpp"
#include "scene/scene_sequence.hpp"

namespace lfd::lightfield {

// How messages name a setting: as `lfd render`'s flag ("--view-cone") or as the Python keyword
// ("view_cone").
enum class SettingNames { kFlags, kKeywords };
std::string setting_name(SettingNames names, std::string_view keyword);

struct RenderSettings {
  std::string method = "g2lf";  // per-view | g2lf | v2lf; g2lf names V2LF for voxel scenes
  bool method_given = false;    // ... only when it is the default, not when asked for
  std::optional<int> views;
  std::optional<int> cols, rows;  // together or neither
  std::optional<display::ViewSize> size;
  std::optional<double> view_cone_deg;
  std::optional<render::CameraSpec> camera;
  float orbit_deg = 0.0f;       // turns the scene's framing (no camera)
  float focal_distance = 0.0f;  // 0: the distance to the camera's look-at point
  render::G2lfOptions planes;   // chunks, plane_scale, d_shift; the rest by name below
  // empty: nearest for the quilt's swizzle, bilinear for the direct pass (closer to the
  // continuous views there, docs/rendering.md); given: both.
  std::string filter;
  std::string precision = "u8", binning = "mixed";
  std::optional<int> split_levels;  // V2LF only
  bool no_plane_lowpass = false;    // V2LF only
  std::optional<glm::vec3> background;  // unset: black behind Gaussians, the voxels' own
  std::string raster = "hardware";      // GL, Gaussians: hardware | compute | auto (docs/gpu.md)
  bool raster_given = false;            // refused with the CPU backend when asked for
  int frame = 0;                        // a moving scene's frame (docs/record.md "Scenes that move")
  bool frame_given = false;             // refused for a still scene when asked for
};

// InputError naming the setting for what needs no scene: views outside 1..256, a cone outside
// (0, 170) degrees, a size outside [1, 16384], cols without rows, names of unknown choices.
void check_render_settings(const RenderSettings& settings, SettingNames names);

// InputError naming the setting when a raster path is asked of the CPU backend (`cpu_asked`: the
// caller asked for the CPU, not fell back to it).
void check_backend_settings(const RenderSettings& settings, bool cpu_asked, SettingNames names);

// The file of the frame a render of `settings` shows from `sequence` (`moving`: the scene was
// named as a sequence, scene/scene_sequence.hpp): frame K of a moving scene, framed as its first
// (render with plan_render_views of the first frame, as `lfd record` frames it). InputError
// naming the setting for a frame asked of a still scene or beyond the sequence.
const std::filesystem::path& scene_frame_file(const RenderSettings& settings, const scene::SceneSequence& sequence,
                                              bool moving, SettingNames names);

// The renderer's options for a scene of `kind` called `scene_name` on `backend`: the method (g2lf
// and v2lf each for its kind; V2LF's own options refused for Gaussians), the planes, the
// background, the raster path (auto left for the renderer to resolve); f16 planes only on GL.
// InputError naming the setting.
RendererOptions renderer_options(const RenderSettings& settings, scene::SceneKind kind, const std::string& scene_name,
                                 Backend backend, SettingNames names);

// The settings' request of the view plan for `display` (null: none).
ViewRequest view_request(const RenderSettings& settings, const display::Calibration* display);

// The plan (view_plan.hpp) with a refused grid named as the settings that chose it.
ViewPlan plan_render_views(const RenderSettings& settings, const display::Calibration* display,
                           const scene::Scene& scene, SettingNames names);
// The same for a request of the settings that the caller changed (`lfd record`: each frame's camera).
ViewPlan plan_render_views(const RenderSettings& settings, const ViewRequest& request, const scene::Scene& scene,
                           SettingNames names);

}  // namespace lfd::lightfield
