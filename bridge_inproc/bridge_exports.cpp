// The C functions of Bridge 2.6's in-process library (bridge_inproc.h, docs/bridge-inproc.md):
// each checks its pointers, calls the Runtime, and turns any refusal into false and one log line.
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "bridge_inproc/bridge_inproc.h"
#include "bridge_inproc/bridge_log.hpp"
#include "bridge_inproc/bridge_registration.hpp"
#include "bridge_inproc/bridge_runtime.hpp"
#include "bridge_inproc/caller_texture.hpp"
#include "bridge_inproc/holoplay_values.hpp"
#include "bridge_inproc/wide_text.hpp"
#include "display/display_quilt.hpp"
#include "rgbd/rgbd_quilt.hpp"
#include "rgbd/rgbd_view_model.hpp"
#include "util/image.hpp"
#include "util/version.hpp"

using namespace lfd;
using namespace lfd::bridge;

namespace {

constexpr unsigned kRgbaFormat = 0x1908;

// Runs `body`; false and a log line naming `call` on any refusal or failure.
template <typename F>
bool guarded(const char* call, F&& body) noexcept {
  try {
    body();
    return true;
  } catch (const std::exception& e) {
    log_line(call, e.what());
  } catch (...) {
    log_line(call, "unknown failure");
  }
  return false;
}

template <typename... P>
void require_pointers(P*... pointers) {
  if (((pointers == nullptr) || ...)) refuse("a required pointer argument is null");
}

Runtime& runtime() { return Runtime::instance(); }

// Sizes arrive as unsigned long from the Python SDK and as unsigned int from bridge.h's
// declarations of some calls; only the low 32 bits are meaningful in either.
int size_arg(unsigned long value, const char* what) {
  const unsigned long v = value & 0xFFFFFFFFul;
  if (v == 0 || v > 65536) refuse(fmt::format("{} {} is outside 1..65536", what, v));
  return int(v);
}

double positive_arg(float value, const char* what) {
  if (!std::isfinite(value) || value <= 0) refuse(fmt::format("{} {} is not a positive number", what, value));
  return value;
}

render::QuiltLayout quilt_layout(unsigned long width, unsigned long height, unsigned long vx, unsigned long vy,
                                 float aspect, const char* call) {
  render::QuiltLayout layout;
  layout.width = size_arg(width, "width");
  layout.height = size_arg(height, "height");
  layout.cols = size_arg(vx, "vx (columns)");
  layout.rows = size_arg(vy, "vy (rows)");
  layout.views = layout.cols * layout.rows;
  layout.aspect = positive_arg(aspect, "aspect");
  layout.check(call);
  return layout;
}

void write_calibration(const BridgeDisplay& d, float* center, float* pitch, float* slope, int* width, int* height,
                       float* dpi, float* flip_x, int* inv_view, float* viewcone, float* fringe,
                       int* cell_pattern_mode, int* number_of_cells, CalibrationSubpixelCell* cells) {
  require_pointers(center, pitch, slope, width, height, dpi, flip_x, inv_view, viewcone, fringe, cell_pattern_mode,
                   number_of_cells);
  const display::DisplayCalibration& c = d.calibration.display;
  *center = float(c.center_periods);
  *pitch = float(c.pitch_lpi);
  *slope = float(c.slope);
  *width = c.screen_w;
  *height = c.screen_h;
  *dpi = float(c.dpi);
  *flip_x = c.flip_image_x ? 1.f : 0.f;
  *inv_view = c.inv_view ? 1 : 0;
  *viewcone = float(c.view_cone_deg);
  *fringe = float(c.fringe);
  *cell_pattern_mode = c.cell_pattern_mode;
  const int n = int(c.subpixel_cells.size());
  if (cells) {
    const int capacity = std::min(*number_of_cells, n);
    for (int i = 0; i < capacity; ++i) {
      const display::SubpixelCell& s = c.subpixel_cells[size_t(i)];
      cells[i] = {float(s.r_x), float(s.r_y), float(s.g_x), float(s.g_y), float(s.b_x), float(s.b_y)};
    }
  }
  *number_of_cells = n;
}

void write_default_quilt(const BridgeDisplay& d, float* aspect, int* quilt_width, int* quilt_height,
                         int* quilt_columns, int* quilt_rows) {
  require_pointers(aspect, quilt_width, quilt_height, quilt_columns, quilt_rows);
  const DefaultQuilt q = default_quilt(d.calibration);
  *aspect = q.aspect;
  *quilt_width = q.width;
  *quilt_height = q.height;
  *quilt_columns = q.cols;
  *quilt_rows = q.rows;
}

// A HoloPlay value of a window's or a display's unit.
template <typename T, typename Get>
bool holoplay_of_window(const char* call, WINDOW_HANDLE wnd, T* out, Get get) {
  return guarded(call, [&] {
    require_pointers(out);
    *out = get(holoplay_values(runtime().window(wnd).display.calibration.display));
  });
}
template <typename T, typename Get>
bool holoplay_of_display(const char* call, unsigned long index, T* out, Get get) {
  return guarded(call, [&] {
    require_pointers(out);
    *out = get(holoplay_values(runtime().display(index).calibration.display));
  });
}

Image8 image_from_bottom_up(const uint8_t* bytes, int width, int height, int channels, bool bgra) {
  Image8 image(width, height, 3);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const uint8_t* p = bytes + (size_t(height - 1 - y) * width + x) * channels;
      for (int c = 0; c < 3; ++c) image.at(x, y, c) = channels == 1 ? p[0] : p[bgra ? 2 - c : c];
    }
  return image;
}

bool not_on_linux(const char* call) {
  log_line(call, "DirectX and Metal are not available on Linux: use the _gl calls");
  return false;
}

}  // namespace

extern "C" {

// ---- lifetime ---------------------------------------------------------------------------------

bool initialize_bridge(const char* app_name) {
  return guarded("initialize_bridge", [&] { runtime().initialize(text_of_c_or_wide(app_name, "app_name")); });
}

bool uninitialize_bridge(void) {
  return guarded("uninitialize_bridge", [&] { runtime().uninitialize(); });
}

bool get_bridge_version(unsigned long* major, unsigned long* minor, unsigned long* build,
                        int* number_of_postfix_wchars, wchar_t* postfix) {
  return guarded("get_bridge_version", [&] {
    require_pointers(major, minor, build, number_of_postfix_wchars);
    *major = kBridgeMajor;
    *minor = kBridgeMinor;
    *build = kBridgeBuild;
    write_wide("lfd " + version_info().version, number_of_postfix_wchars, postfix);
  });
}

// ---- windows ----------------------------------------------------------------------------------

bool instance_window_gl(WINDOW_HANDLE* wnd, unsigned long display_index) {
  return guarded("instance_window_gl", [&] {
    require_pointers(wnd);
    *wnd = runtime().make_window(display_index, false);
  });
}

bool instance_offscreen_window(WINDOW_HANDLE* wnd, unsigned long width, unsigned long height,
                               const wchar_t* calibration_path) {
  return guarded("instance_offscreen_window", [&] {
    require_pointers(wnd);
    const std::string path = text_of_c_or_wide(calibration_path, "calibration_path");
    *wnd = runtime().make_offscreen_window(size_arg(width, "width"), size_arg(height, "height"), path);
  });
}

bool instance_offscreen_window_gl(WINDOW_HANDLE* wnd, unsigned long display_index) {
  return guarded("instance_offscreen_window_gl", [&] {
    require_pointers(wnd);
    *wnd = runtime().make_window(display_index, true);
  });
}

bool get_offscreen_window_texture_gl(WINDOW_HANDLE wnd, unsigned long long* texture, unsigned int* format,
                                     unsigned long* width, unsigned long* height) {
  return guarded("get_offscreen_window_texture_gl", [&] {
    require_pointers(texture, format, width, height);
    const WindowRecord record = runtime().window(wnd);
    if (!record.offscreen) refuse(fmt::format("window {} is not an offscreen window", wnd));
    const RgbaPixels panel = runtime().read_panel(wnd);
    const unsigned name = upload_to_caller_texture(record.caller_panel_texture, panel);
    runtime().set_caller_panel_texture(wnd, name);
    *texture = name;
    *format = kRgbaFormat;
    *width = static_cast<unsigned long>(panel.width);
    *height = static_cast<unsigned long>(panel.height);
  });
}

bool show_window(WINDOW_HANDLE wnd, bool flag) {
  return guarded("show_window", [&] { runtime().show(wnd, flag); });
}

bool get_window_dimensions(WINDOW_HANDLE wnd, unsigned long* width, unsigned long* height) {
  return guarded("get_window_dimensions", [&] {
    require_pointers(width, height);
    const WindowPlacement p = runtime().window(wnd).placement;
    *width = static_cast<unsigned long>(p.width);
    *height = static_cast<unsigned long>(p.height);
  });
}

bool get_window_position(WINDOW_HANDLE wnd, long* x, long* y) {
  return guarded("get_window_position", [&] {
    require_pointers(x, y);
    const WindowPlacement p = runtime().window(wnd).placement;
    *x = p.x;
    *y = p.y;
  });
}

bool get_max_texture_size(WINDOW_HANDLE wnd, unsigned long* size) {
  return guarded("get_max_texture_size", [&] {
    require_pointers(size);
    *size = static_cast<unsigned long>(runtime().window(wnd).placement.max_texture_size);
  });
}

bool get_display_for_window(WINDOW_HANDLE wnd, unsigned long* display_index) {
  return guarded("get_display_for_window", [&] {
    require_pointers(display_index);
    const WindowRecord record = runtime().window(wnd);
    if (!record.display_index) refuse(fmt::format("window {} was made from a calibration file, not a display", wnd));
    *display_index = *record.display_index;
  });
}

// ---- drawing ----------------------------------------------------------------------------------

bool set_interop_quilt_texture_gl(WINDOW_HANDLE wnd, unsigned long long texture, unsigned int format,
                                  unsigned long width, unsigned long height, unsigned long vx, unsigned long vy,
                                  float aspect, float zoom) {
  return guarded("set_interop_quilt_texture_gl", [&] {
    runtime().window(wnd);
    check_readable_format(format);
    if (texture == 0 || texture > std::numeric_limits<unsigned>::max()) refuse(fmt::format("texture {}", texture));
    QuiltTextureSettings s;
    s.texture = texture;
    s.format = format;
    s.layout = quilt_layout(width, height, vx, vy, aspect, "set_interop_quilt_texture_gl");
    s.zoom = positive_arg(zoom, "zoom");
    runtime().set_quilt_texture(wnd, s);
  });
}

bool draw_interop_quilt_texture_gl(WINDOW_HANDLE wnd, unsigned long long texture, unsigned int format,
                                   unsigned long width, unsigned long height, unsigned long vx, unsigned long vy,
                                   float aspect, float zoom) {
  return guarded("draw_interop_quilt_texture_gl", [&] {
    runtime().window(wnd);
    check_readable_format(format);
    if (texture == 0 || texture > std::numeric_limits<unsigned>::max()) refuse(fmt::format("texture {}", texture));
    const render::QuiltLayout layout = quilt_layout(width, height, vx, vy, aspect, "draw_interop_quilt_texture_gl");
    const double z = positive_arg(zoom, "zoom");
    RgbaPixels pixels = read_caller_texture(unsigned(texture), layout.width, layout.height, runtime().take_buffer());
    runtime().draw_quilt(wnd, std::move(pixels), layout, z);
  });
}

bool draw_interop_rgbd_texture_gl(WINDOW_HANDLE wnd, unsigned long long texture, unsigned int format,
                                  unsigned long width, unsigned long height, unsigned long quilt_width,
                                  unsigned long quilt_height, unsigned long vx, unsigned long vy, float aspect,
                                  float focus, float depthiness, float zoom, int depth_loc) {
  return guarded("draw_interop_rgbd_texture_gl", [&] {
    runtime().window(wnd);
    check_readable_format(format);
    if (texture == 0 || texture > std::numeric_limits<unsigned>::max()) refuse(fmt::format("texture {}", texture));
    const render::QuiltLayout layout =
        quilt_layout(quilt_width, quilt_height, vx, vy, aspect, "draw_interop_rgbd_texture_gl");
    if (depth_loc < 0 || depth_loc > 3) refuse(fmt::format("depth_loc {} is not 0..3", depth_loc));
    rgbd::RgbdOptions options;
    options.depth_loc = rgbd::DepthLocation(depth_loc);
    options.focus = focus;
    options.depthiness = depthiness;
    options.zoom = zoom;
    options.check("draw_interop_rgbd_texture_gl");
    RgbaPixels pixels = read_caller_texture(unsigned(texture), size_arg(width, "width"), size_arg(height, "height"),
                                            runtime().take_buffer());
    runtime().draw_rgbd(wnd, std::move(pixels), options, layout);
  });
}

bool quiltify_rgbd(WINDOW_HANDLE wnd, unsigned long columns, unsigned long rows, unsigned long views, float aspect,
                   float zoom, float cam_dist, float fov, float crop_pos_x, float crop_pos_y,
                   unsigned long depth_inversion, unsigned long chroma_depth, unsigned long depth_loc,
                   float depthiness, float depth_cutoff, float focus, const wchar_t* input_path,
                   const wchar_t* output_path) {
  (void)cam_dist;  // lfd's RGB-D model has no camera distance or field of view (docs/bridge-inproc.md)
  (void)fov;
  return guarded("quiltify_rgbd", [&] {
    const WindowRecord record = runtime().window(wnd);
    const std::string in = text_of_c_or_wide(input_path, "input_path");
    const std::string out = text_of_c_or_wide(output_path, "output_path");
    rgbd::RgbdOptions options;
    if ((depth_loc & 0xFFFFFFFFul) > 3) refuse(fmt::format("depth_loc {} is not 0..3", depth_loc));
    options.depth_loc = rgbd::DepthLocation(depth_loc & 3);
    options.depth_inversion = (depth_inversion & 0xFFFFFFFFul) != 0;
    options.chroma_depth = (chroma_depth & 0xFFFFFFFFul) != 0;
    options.depthiness = depthiness;
    options.depth_cutoff = depth_cutoff;
    options.focus = focus;
    options.zoom = zoom;
    options.crop_pos_x = crop_pos_x;
    options.crop_pos_y = crop_pos_y;
    options.check("quiltify_rgbd");
    const int cols = size_arg(columns, "columns"), grid_rows = size_arg(rows, "rows");
    const int view_count = size_arg(views, "views");
    if (view_count > cols * grid_rows) refuse(fmt::format("{} views do not fit {}x{} tiles", view_count, cols, grid_rows));
    const double view_aspect = positive_arg(aspect, "aspect");
    const ImageF frame = to_float(read_image(in, 3));
    render::QuiltLayout layout = rgbd::rgbd_quilt_layout(frame.width, frame.height, options.depth_loc, view_count);
    const int tile_h = layout.tile_height();
    const int tile_w = std::max(1, int(std::lround(tile_h * view_aspect)));
    layout.cols = cols;
    layout.rows = grid_rows;
    layout.views = view_count;
    layout.aspect = view_aspect;
    layout.width = tile_w * cols;
    layout.height = tile_h * grid_rows;
    const ImageF quilt = rgbd::render_rgbd_quilt(frame, options, layout,
                                                 display::effective_view_cone_deg(record.display.calibration));
    write_png(out, to_uint8(quilt));
  });
}

bool save_texture_to_file_gl(WINDOW_HANDLE wnd, const char* filename, unsigned long long texture, unsigned int format,
                             unsigned long width, unsigned long height) {
  return guarded("save_texture_to_file_gl", [&] {
    runtime().window(wnd);
    const std::string path = text_of_c_or_wide(filename, "filename");
    check_readable_format(format);
    if (texture == 0 || texture > std::numeric_limits<unsigned>::max()) refuse(fmt::format("texture {}", texture));
    const int w = size_arg(width, "width"), h = size_arg(height, "height");
    const RgbaPixels pixels = read_caller_texture(unsigned(texture), w, h);
    write_png(path, image_from_bottom_up(pixels.bytes.data(), w, h, 4, false));
  });
}

bool save_image_to_file(WINDOW_HANDLE wnd, const char* filename, void* image, unsigned int format,
                        unsigned long width, unsigned long height) {
  return guarded("save_image_to_file", [&] {
    runtime().window(wnd);
    const std::string path = text_of_c_or_wide(filename, "filename");
    require_pointers(image);
    int channels = 0;
    switch (format) {
      case 0x1907: channels = 3; break;          // RGB
      case 0x1908: case 0x80E1: channels = 4; break;  // RGBA, BGRA
      case 0x1903: channels = 1; break;          // Red
      default: refuse(fmt::format("pixel format 0x{:X}: save_image_to_file takes 8-bit RGB, RGBA, BGRA or Red", format));
    }
    const int w = size_arg(width, "width"), h = size_arg(height, "height");
    write_png(path, image_from_bottom_up(static_cast<const uint8_t*>(image), w, h, channels, format == 0x80E1));
  });
}

// ---- queries ----------------------------------------------------------------------------------

bool get_displays(int* number_of_indices, unsigned long* indices) {
  return guarded("get_displays", [&] {
    require_pointers(number_of_indices);
    const std::vector<unsigned long> all = runtime().display_indices();
    if (indices) {
      const int n = std::min(*number_of_indices, int(all.size()));
      for (int i = 0; i < n; ++i) indices[i] = all[size_t(i)];
    }
    *number_of_indices = int(all.size());
  });
}

bool get_calibration(WINDOW_HANDLE wnd, float* center, float* pitch, float* slope, int* width, int* height, float* dpi,
                     float* flip_x, int* invView, float* viewcone, float* fringe, int* cell_pattern_mode,
                     int* number_of_cells, CalibrationSubpixelCell* cells) {
  return guarded("get_calibration", [&] {
    write_calibration(runtime().window(wnd).display, center, pitch, slope, width, height, dpi, flip_x, invView,
                      viewcone, fringe, cell_pattern_mode, number_of_cells, cells);
  });
}

bool get_device_name(WINDOW_HANDLE wnd, int* number_of_device_name_wchars, wchar_t* device_name) {
  return guarded("get_device_name",
                 [&] { write_wide(runtime().window(wnd).display.name, number_of_device_name_wchars, device_name); });
}

bool get_device_serial(WINDOW_HANDLE wnd, int* number_of_serial_wchars, wchar_t* serial) {
  return guarded("get_device_serial",
                 [&] { write_wide(runtime().window(wnd).display.serial, number_of_serial_wchars, serial); });
}

bool get_device_type(WINDOW_HANDLE wnd, int* hw_enum) {
  return guarded("get_device_type", [&] {
    require_pointers(hw_enum);
    *hw_enum = runtime().window(wnd).display.hw_enum;
  });
}

bool get_default_quilt_settings(WINDOW_HANDLE wnd, float* aspect, int* quilt_width, int* quilt_height,
                                int* quilt_columns, int* quilt_rows) {
  return guarded("get_default_quilt_settings", [&] {
    write_default_quilt(runtime().window(wnd).display, aspect, quilt_width, quilt_height, quilt_columns, quilt_rows);
  });
}

bool get_viewcone(WINDOW_HANDLE wnd, float* v) {
  return holoplay_of_window("get_viewcone", wnd, v, [](const HoloPlayValues& h) { return h.viewcone; });
}
bool get_invview(WINDOW_HANDLE wnd, int* v) {
  return holoplay_of_window("get_invview", wnd, v, [](const HoloPlayValues& h) { return h.invview; });
}
bool get_ri(WINDOW_HANDLE wnd, int* v) {
  return holoplay_of_window("get_ri", wnd, v, [](const HoloPlayValues& h) { return h.ri; });
}
bool get_bi(WINDOW_HANDLE wnd, int* v) {
  return holoplay_of_window("get_bi", wnd, v, [](const HoloPlayValues& h) { return h.bi; });
}
bool get_tilt(WINDOW_HANDLE wnd, float* v) {
  return holoplay_of_window("get_tilt", wnd, v, [](const HoloPlayValues& h) { return h.tilt; });
}
bool get_displayaspect(WINDOW_HANDLE wnd, float* v) {
  return holoplay_of_window("get_displayaspect", wnd, v, [](const HoloPlayValues& h) { return h.displayaspect; });
}
bool get_fringe(WINDOW_HANDLE wnd, float* v) {
  return holoplay_of_window("get_fringe", wnd, v, [](const HoloPlayValues& h) { return h.fringe; });
}
bool get_subp(WINDOW_HANDLE wnd, float* v) {
  return holoplay_of_window("get_subp", wnd, v, [](const HoloPlayValues& h) { return h.subp; });
}
bool get_pitch(WINDOW_HANDLE wnd, float* v) {
  return holoplay_of_window("get_pitch", wnd, v, [](const HoloPlayValues& h) { return h.pitch; });
}
bool get_center(WINDOW_HANDLE wnd, float* v) {
  return holoplay_of_window("get_center", wnd, v, [](const HoloPlayValues& h) { return h.center; });
}

bool get_device_name_for_display(unsigned long display_index, int* number_of_device_name_wchars,
                                 wchar_t* device_name) {
  return guarded("get_device_name_for_display", [&] {
    write_wide(runtime().display(display_index).name, number_of_device_name_wchars, device_name);
  });
}

bool get_device_serial_for_display(unsigned long display_index, int* number_of_serial_wchars, wchar_t* serial) {
  return guarded("get_device_serial_for_display",
                 [&] { write_wide(runtime().display(display_index).serial, number_of_serial_wchars, serial); });
}

bool get_dimensions_for_display(unsigned long display_index, unsigned long* width, unsigned long* height) {
  return guarded("get_dimensions_for_display", [&] {
    require_pointers(width, height);
    const display::DisplayCalibration& c = runtime().display(display_index).calibration.display;
    *width = static_cast<unsigned long>(c.screen_w);
    *height = static_cast<unsigned long>(c.screen_h);
  });
}

bool get_window_position_for_display(unsigned long display_index, long* x, long* y) {
  return guarded("get_window_position_for_display", [&] {
    require_pointers(x, y);
    const auto [px, py] = runtime().display_position(display_index);
    *x = px;
    *y = py;
  });
}

bool get_device_type_for_display(unsigned long display_index, int* hw_enum) {
  return guarded("get_device_type_for_display", [&] {
    require_pointers(hw_enum);
    *hw_enum = runtime().display(display_index).hw_enum;
  });
}

bool get_calibration_for_display(unsigned long display_index, float* center, float* pitch, float* slope, int* width,
                                 int* height, float* dpi, float* flip_x, int* invView, float* viewcone, float* fringe,
                                 int* cell_pattern_mode, int* number_of_cells, CalibrationSubpixelCell* cells) {
  return guarded("get_calibration_for_display", [&] {
    write_calibration(runtime().display(display_index), center, pitch, slope, width, height, dpi, flip_x, invView,
                      viewcone, fringe, cell_pattern_mode, number_of_cells, cells);
  });
}

bool get_invview_for_display(unsigned long i, int* v) {
  return holoplay_of_display("get_invview_for_display", i, v, [](const HoloPlayValues& h) { return h.invview; });
}
bool get_ri_for_display(unsigned long i, int* v) {
  return holoplay_of_display("get_ri_for_display", i, v, [](const HoloPlayValues& h) { return h.ri; });
}
bool get_bi_for_display(unsigned long i, int* v) {
  return holoplay_of_display("get_bi_for_display", i, v, [](const HoloPlayValues& h) { return h.bi; });
}
bool get_tilt_for_display(unsigned long i, float* v) {
  return holoplay_of_display("get_tilt_for_display", i, v, [](const HoloPlayValues& h) { return h.tilt; });
}
bool get_displayaspect_for_display(unsigned long i, float* v) {
  return holoplay_of_display("get_displayaspect_for_display", i, v,
                             [](const HoloPlayValues& h) { return h.displayaspect; });
}
bool get_fringe_for_display(unsigned long i, float* v) {
  return holoplay_of_display("get_fringe_for_display", i, v, [](const HoloPlayValues& h) { return h.fringe; });
}
bool get_subp_for_display(unsigned long i, float* v) {
  return holoplay_of_display("get_subp_for_display", i, v, [](const HoloPlayValues& h) { return h.subp; });
}
bool get_viewcone_for_display(unsigned long i, float* v) {
  return holoplay_of_display("get_viewcone_for_display", i, v, [](const HoloPlayValues& h) { return h.viewcone; });
}
bool get_pitch_for_display(unsigned long i, float* v) {
  return holoplay_of_display("get_pitch_for_display", i, v, [](const HoloPlayValues& h) { return h.pitch; });
}
bool get_center_for_display(unsigned long i, float* v) {
  return holoplay_of_display("get_center_for_display", i, v, [](const HoloPlayValues& h) { return h.center; });
}

bool get_default_quilt_settings_for_display(unsigned long display_index, float* aspect, int* quilt_width,
                                            int* quilt_height, int* quilt_columns, int* quilt_rows) {
  return guarded("get_default_quilt_settings_for_display", [&] {
    write_default_quilt(runtime().display(display_index), aspect, quilt_width, quilt_height, quilt_columns,
                        quilt_rows);
  });
}

// ---- DirectX and Metal ------------------------------------------------------------------------

bool device_from_resource_dx(void*, void**) { return not_on_linux("device_from_resource_dx"); }
bool release_device_dx(void*) { return not_on_linux("release_device_dx"); }
bool instance_window_dx(void*, WINDOW_HANDLE*, unsigned long) { return not_on_linux("instance_window_dx"); }
bool instance_offscreen_window_dx(void*, WINDOW_HANDLE*, unsigned long) {
  return not_on_linux("instance_offscreen_window_dx");
}
bool register_texture_dx(WINDOW_HANDLE, void*) { return not_on_linux("register_texture_dx"); }
bool unregister_texture_dx(WINDOW_HANDLE, void*) { return not_on_linux("unregister_texture_dx"); }
bool save_texture_to_file_dx(WINDOW_HANDLE, wchar_t*, void*) { return not_on_linux("save_texture_to_file_dx"); }
bool draw_interop_quilt_texture_dx(WINDOW_HANDLE, void*, unsigned long, unsigned long, float, float) {
  return not_on_linux("draw_interop_quilt_texture_dx");
}
bool draw_interop_rgbd_texture_dx(WINDOW_HANDLE, void*, unsigned int, unsigned int, unsigned int, unsigned int,
                                  unsigned int, unsigned int, float, float, float, float, int) {
  return not_on_linux("draw_interop_rgbd_texture_dx");
}
bool create_texture_dx(WINDOW_HANDLE, unsigned long, unsigned long, void**) { return not_on_linux("create_texture_dx"); }
bool release_texture_dx(WINDOW_HANDLE, void*) { return not_on_linux("release_texture_dx"); }
bool copy_texture_dx(WINDOW_HANDLE, void*, void*) { return not_on_linux("copy_texture_dx"); }
bool get_offscreen_window_texture_dx(WINDOW_HANDLE, void**) { return not_on_linux("get_offscreen_window_texture_dx"); }
bool instance_window_metal(void*, WINDOW_HANDLE*, unsigned long) { return not_on_linux("instance_window_metal"); }
bool instance_offscreen_window_metal(void*, WINDOW_HANDLE*, unsigned long) {
  return not_on_linux("instance_offscreen_window_metal");
}
bool create_metal_texture_with_iosurface(WINDOW_HANDLE, void*, void**) {
  return not_on_linux("create_metal_texture_with_iosurface");
}
bool copy_metal_texture(WINDOW_HANDLE, void*, void*) { return not_on_linux("copy_metal_texture"); }
bool release_metal_texture(WINDOW_HANDLE, void*) { return not_on_linux("release_metal_texture"); }
bool save_metal_texture_to_file(WINDOW_HANDLE, char*, void*, unsigned int, unsigned long, unsigned long) {
  return not_on_linux("save_metal_texture_to_file");
}
bool draw_interop_quilt_texture_metal(WINDOW_HANDLE, void*, unsigned long, unsigned long, float, float) {
  return not_on_linux("draw_interop_quilt_texture_metal");
}
bool get_offscreen_window_texture_metal(WINDOW_HANDLE, void**) {
  return not_on_linux("get_offscreen_window_texture_metal");
}

}  // extern "C"
