#include "lightfield/render_settings.hpp"

#include <algorithm>

#include "gpu/gl/raster_path.hpp"
#include "util/error.hpp"

namespace lfd::lightfield {

std::string setting_name(SettingNames names, std::string_view keyword) {
  std::string name(keyword);
  if (names == SettingNames::kKeywords) return name;
  std::replace(name.begin(), name.end(), '_', '-');
  return "--" + name;
}

namespace {

void check_choice(const std::string& value, std::initializer_list<const char*> choices, const char* keyword,
                  SettingNames names) {
  for (const char* choice : choices)
    if (value == choice) return;
  std::string list;
  for (const char* choice : choices) list += (list.empty() ? "" : ", ") + std::string(choice);
  throw_input_error("{}: '{}' is not one of {}", setting_name(names, keyword), value, list);
}

}  // namespace

void check_render_settings(const RenderSettings& s, SettingNames names) {
  const auto name = [names](std::string_view keyword) { return setting_name(names, keyword); };
  check_choice(s.method, {"per-view", "g2lf", "v2lf"}, "method", names);
  if (!s.filter.empty()) check_choice(s.filter, {"nearest", "bilinear"}, "filter", names);
  check_choice(s.precision, {"u8", "f16", "f32"}, "precision", names);
  check_choice(s.binning, {"mixed", "quantile"}, "binning", names);
  check_choice(s.raster, {"hardware", "compute", "auto"}, "raster", names);
  if (s.frame < 0) throw_input_error("{}: {} must be 0 or more", name("frame"), s.frame);
  if (s.views && (*s.views < 1 || *s.views > 256)) throw_input_error("{}: {} is outside 1..256", name("views"), *s.views);
  if (s.view_cone_deg && !(*s.view_cone_deg > 0.0 && *s.view_cone_deg < 170.0))
    throw_input_error("{}: {} must lie in (0, 170) degrees", name("view_cone"), *s.view_cone_deg);
  if (s.cols.has_value() != s.rows.has_value())
    throw_input_error("{}: needs {} too", name(s.cols ? "cols" : "rows"), name(s.cols ? "rows" : "cols"));
  if (s.size && (s.size->width < 1 || s.size->height < 1 || s.size->width > 16384 || s.size->height > 16384))
    throw_input_error("{}: {}x{} must be two integers in [1, 16384]", name("size"), s.size->width, s.size->height);
}

void check_backend_settings(const RenderSettings& s, bool cpu_asked, SettingNames names) {
  if (cpu_asked && s.raster_given)
    throw_input_error("{}: chooses how the GL backend draws; the CPU backend has no raster paths",
                      setting_name(names, "raster"));
}

const std::filesystem::path& scene_frame_file(const RenderSettings& s, const scene::SceneSequence& sequence,
                                              bool moving, SettingNames names) {
  if (s.frame_given && !moving)
    throw_input_error("{}: {} is one scene; a moving one is a pattern (name_%04d.ply), a folder or a list",
                      setting_name(names, "frame"), sequence.source);
  if (s.frame < 0 || size_t(s.frame) >= sequence.frames.size())
    throw_input_error("{}: {} is outside the {} frames of {}", setting_name(names, "frame"), s.frame,
                      sequence.frames.size(), sequence.source);
  return sequence.frames[size_t(s.frame)];
}

RendererOptions renderer_options(const RenderSettings& s, scene::SceneKind kind, const std::string& scene_name,
                                 Backend backend, SettingNames names) {
  const auto name = [names](std::string_view keyword) { return setting_name(names, keyword); };
  const bool voxels = kind == scene::SceneKind::kVoxels;
  if (voxels && s.method == "g2lf" && s.method_given)
    throw_input_error("{}: g2lf is for Gaussian scenes; {} is a voxel scene (per-view or v2lf)", name("method"),
                      scene_name);
  if (!voxels && s.method == "v2lf")
    throw_input_error("{}: v2lf is for voxel scenes; {} holds Gaussians (g2lf)", name("method"), scene_name);
  if (!voxels && (s.split_levels || s.no_plane_lowpass))
    throw_input_error("{}, {}: V2LF options for voxel scenes; {} holds Gaussians", name("split_levels"),
                      name("no_plane_lowpass"), scene_name);
  RendererOptions options;
  options.backend = backend;
  options.method = s.method == "per-view" ? Method::kPerView : Method::kSweepingPlanes;
  options.planes = s.planes;
  if (!s.filter.empty()) options.planes.filter = options.direct_filter = render::parse_plane_filter(s.filter);
  // f16 exists only as a GPU texture format; the CPU planes are u8 or f32.
  if (s.precision == "f16") {
    if (backend == Backend::kCpu)
      throw_input_error("{}: f16 (RGBA16F planes) needs the GL backend; the CPU stores u8 or f32", name("precision"));
    options.gl.plane_format = gpu::PlaneFormat::kRgba16f;
  }
  options.planes.precision = render::parse_plane_precision(s.precision == "f16" ? "f32" : s.precision);
  options.planes.binning = render::parse_chunk_binning(s.binning);
  options.gl.raster = gpu::parse_raster_path(s.raster);
  options.planes.adaptive_filter = !s.no_plane_lowpass;
  options.planes.check();
  options.split_levels = s.split_levels.value_or(0);
  options.background = s.background;
  return options;
}

ViewRequest view_request(const RenderSettings& s, const display::Calibration* display) {
  ViewRequest r;
  r.display = display;
  r.views = s.views;
  r.view_cone_deg = s.view_cone_deg;
  r.camera = s.camera;
  r.orbit_deg = s.orbit_deg;
  r.size = s.size;
  if (s.focal_distance > 0.0f) r.focal_distance = s.focal_distance;
  if (s.cols && s.rows) r.grid = display::QuiltGrid{*s.cols, *s.rows};
  return r;
}

ViewPlan plan_render_views(const RenderSettings& s, const display::Calibration* display, const scene::Scene& scene,
                           SettingNames names) {
  return plan_render_views(s, view_request(s, display), scene, names);
}

ViewPlan plan_render_views(const RenderSettings& s, const ViewRequest& request, const scene::Scene& scene,
                           SettingNames names) {
  try {
    return plan_views(request, &scene);
  } catch (const InputError& e) {
    // The plan names its field ("grid: ..."); the caller gave it as cols and rows.
    const std::string why = e.what();
    if (s.cols && why.starts_with("grid: "))
      throw_input_error("{}/{}: {}", setting_name(names, "cols"), setting_name(names, "rows"), why.substr(6));
    throw;
  }
}

}  // namespace lfd::lightfield
