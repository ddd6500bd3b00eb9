/* lfd's in-process Bridge library (docs/bridge-inproc.md): the C functions of Looking Glass
 * Bridge 2.6's libbridge_inproc, with the same names, argument types and return conventions, so
 * a client written for the vendor's library (the Bridge Python SDK through ctypes, the native
 * samples' Controller through dlopen) loads lfd's instead. Written from what each function does;
 * the vendor's header is not copied.
 *
 * Conventions every function follows:
 *  - every function returns true on success and false on a bad call (an unknown window, texture
 *    0 or one that does not exist in the caller's current context, an unsupported pixel format,
 *    zero sizes or grids, null output pointers, a call before initialize_bridge, a calibration
 *    that cannot be read); a false return writes one line to the library's log (stderr, and the
 *    file named by LFD_BRIDGE_LOG) and never ends the process;
 *  - sizes of strings and arrays are asked for in two calls: first with the buffer null (the
 *    count is written), then with a buffer of that many elements;
 *  - strings are wchar_t (32-bit on Linux), counts include the terminating zero;
 *  - window handles are small non-zero numbers that fit 32 bits (the Python SDK passes them as
 *    c_uint32); display indices are those get_displays lists, 0xFFFFFFFF meaning the first one.
 */
#ifndef LFD_BRIDGE_INPROC_H
#define LFD_BRIDGE_INPROC_H

#include <stdbool.h>
#include <wchar.h>

#if defined(LFD_BRIDGE_INPROC_BUILDING)
#define LFD_BRIDGE_API __attribute__((visibility("default")))
#else
#define LFD_BRIDGE_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

typedef unsigned long WINDOW_HANDLE;

/* The display index meaning "the first Looking Glass" (the 32-bit all-ones value). */
#define LFD_BRIDGE_FIRST_LOOKING_GLASS_DEVICE 0xFFFFFFFFul

/* Pixel formats as Bridge numbers them (the GL enums of the formats, and 0x01 for YCoCg). */
enum LfdBridgePixelFormat {
  LFD_BRIDGE_NO_FORMAT = 0x0,
  LFD_BRIDGE_RGB = 0x1907,
  LFD_BRIDGE_RGBA = 0x1908,
  LFD_BRIDGE_BGRA = 0x80E1,
  LFD_BRIDGE_RED = 0x1903,
  LFD_BRIDGE_RGB_DXT1 = 0x83F0,
  LFD_BRIDGE_RGBA_DXT5 = 0x83F3,
  LFD_BRIDGE_YCOCG_DXT5 = 0x01,
  LFD_BRIDGE_A_RGTC1 = 0x8DBB,
  LFD_BRIDGE_SRGB = 0x8C41,
  LFD_BRIDGE_SRGB_A = 0x8C43,
  LFD_BRIDGE_R32F = 0x822E,
  LFD_BRIDGE_RGBA32F = 0x8814,
  LFD_BRIDGE_RGBA_INTEGER = 0x8D99,
  LFD_BRIDGE_RGB10_A2 = 0x8059
};

/* One Gen3 subpixel cell: each colour's offset from the pixel centre, in pixels. */
typedef struct CalibrationSubpixelCell {
  float ROffsetX, ROffsetY, GOffsetX, GOffsetY, BOffsetX, BOffsetY;
} CalibrationSubpixelCell;

/* ---- lifetime ---------------------------------------------------------------------------- */
/* Reads lfd's bridge settings (lfd bridge register), finds the displays; app_name is for the log
 * (a char string, or a wchar_t string as the Python SDK passes it). */
LFD_BRIDGE_API bool initialize_bridge(const char* app_name);
/* Closes every window and the drawing thread. True even when nothing was initialised. */
LFD_BRIDGE_API bool uninitialize_bridge(void);
/* 2.6.x and lfd's version as the postfix (wchar_t, two calls). */
LFD_BRIDGE_API bool get_bridge_version(unsigned long* major, unsigned long* minor, unsigned long* build,
                                       int* number_of_postfix_wchars, wchar_t* postfix);

/* ---- windows ----------------------------------------------------------------------------- */
LFD_BRIDGE_API bool instance_window_gl(WINDOW_HANDLE* wnd, unsigned long display_index);
LFD_BRIDGE_API bool instance_offscreen_window(WINDOW_HANDLE* wnd, unsigned long width, unsigned long height,
                                              const wchar_t* calibration_path);
LFD_BRIDGE_API bool instance_offscreen_window_gl(WINDOW_HANDLE* wnd, unsigned long display_index);
/* The last interlaced panel as a texture of the caller's current GL context (made or refreshed by
 * this call; the library owns it until uninitialize_bridge or the next call). */
LFD_BRIDGE_API bool get_offscreen_window_texture_gl(WINDOW_HANDLE wnd, unsigned long long* texture,
                                                    unsigned int* format, unsigned long* width,
                                                    unsigned long* height);
LFD_BRIDGE_API bool show_window(WINDOW_HANDLE wnd, bool flag);
LFD_BRIDGE_API bool get_window_dimensions(WINDOW_HANDLE wnd, unsigned long* width, unsigned long* height);
LFD_BRIDGE_API bool get_window_position(WINDOW_HANDLE wnd, long* x, long* y);
LFD_BRIDGE_API bool get_max_texture_size(WINDOW_HANDLE wnd, unsigned long* size);
LFD_BRIDGE_API bool get_display_for_window(WINDOW_HANDLE wnd, unsigned long* display_index);

/* ---- drawing ----------------------------------------------------------------------------- */
/* texture: a GL_TEXTURE_2D of the context current on the calling thread (GLX or EGL), width x
 * height texels holding vx x vy views (view 0 bottom-left); aspect: a view's width / height;
 * zoom: 1 shows the views as they are, above 1 magnifies each about its centre. */
LFD_BRIDGE_API bool set_interop_quilt_texture_gl(WINDOW_HANDLE wnd, unsigned long long texture, unsigned int format,
                                                 unsigned long width, unsigned long height, unsigned long vx,
                                                 unsigned long vy, float aspect, float zoom);
LFD_BRIDGE_API bool draw_interop_quilt_texture_gl(WINDOW_HANDLE wnd, unsigned long long texture, unsigned int format,
                                                  unsigned long width, unsigned long height, unsigned long vx,
                                                  unsigned long vy, float aspect, float zoom);
/* An RGB-D texture (colour and depth side by side, depth_loc 0 top, 1 bottom, 2 right, 3 left)
 * drawn as a quilt of quilt_width x quilt_height in vx x vy views. The four floats in the order
 * the Python SDK passes them: view aspect, focus (bridge.js units), depthiness, zoom. */
LFD_BRIDGE_API bool draw_interop_rgbd_texture_gl(WINDOW_HANDLE wnd, unsigned long long texture, unsigned int format,
                                                 unsigned long width, unsigned long height, unsigned long quilt_width,
                                                 unsigned long quilt_height, unsigned long vx, unsigned long vy,
                                                 float aspect, float focus, float depthiness, float zoom,
                                                 int depth_loc);
/* An RGB-D picture file to a quilt picture file (PNG). Paths: char or wchar_t strings. */
LFD_BRIDGE_API bool quiltify_rgbd(WINDOW_HANDLE wnd, unsigned long columns, unsigned long rows, unsigned long views,
                                  float aspect, float zoom, float cam_dist, float fov, float crop_pos_x,
                                  float crop_pos_y, unsigned long depth_inversion, unsigned long chroma_depth,
                                  unsigned long depth_loc, float depthiness, float depth_cutoff, float focus,
                                  const wchar_t* input_path, const wchar_t* output_path);
/* The caller's texture (GL rows, bottom-up) to a PNG file (rows top-down). */
LFD_BRIDGE_API bool save_texture_to_file_gl(WINDOW_HANDLE wnd, const char* filename, unsigned long long texture,
                                            unsigned int format, unsigned long width, unsigned long height);
/* 8-bit RGB, RGBA, BGRA or red pixels, rows bottom-up as glReadPixels gives them, to a PNG. */
LFD_BRIDGE_API bool save_image_to_file(WINDOW_HANDLE wnd, const char* filename, void* image, unsigned int format,
                                       unsigned long width, unsigned long height);

/* ---- queries ----------------------------------------------------------------------------- */
LFD_BRIDGE_API bool get_displays(int* number_of_indices, unsigned long* indices);
LFD_BRIDGE_API bool get_calibration(WINDOW_HANDLE wnd, float* center, float* pitch, float* slope, int* width,
                                    int* height, float* dpi, float* flip_x, int* invView, float* viewcone,
                                    float* fringe, int* cell_pattern_mode, int* number_of_cells,
                                    CalibrationSubpixelCell* cells);
LFD_BRIDGE_API bool get_device_name(WINDOW_HANDLE wnd, int* number_of_device_name_wchars, wchar_t* device_name);
LFD_BRIDGE_API bool get_device_serial(WINDOW_HANDLE wnd, int* number_of_serial_wchars, wchar_t* serial);
LFD_BRIDGE_API bool get_device_type(WINDOW_HANDLE wnd, int* hw_enum);
LFD_BRIDGE_API bool get_default_quilt_settings(WINDOW_HANDLE wnd, float* aspect, int* quilt_width,
                                               int* quilt_height, int* quilt_columns, int* quilt_rows);
LFD_BRIDGE_API bool get_viewcone(WINDOW_HANDLE wnd, float* viewcone);
LFD_BRIDGE_API bool get_invview(WINDOW_HANDLE wnd, int* invview);
LFD_BRIDGE_API bool get_ri(WINDOW_HANDLE wnd, int* ri);
LFD_BRIDGE_API bool get_bi(WINDOW_HANDLE wnd, int* bi);
LFD_BRIDGE_API bool get_tilt(WINDOW_HANDLE wnd, float* tilt);
LFD_BRIDGE_API bool get_displayaspect(WINDOW_HANDLE wnd, float* displayaspect);
LFD_BRIDGE_API bool get_fringe(WINDOW_HANDLE wnd, float* fringe);
LFD_BRIDGE_API bool get_subp(WINDOW_HANDLE wnd, float* subp);
LFD_BRIDGE_API bool get_pitch(WINDOW_HANDLE wnd, float* pitch);
LFD_BRIDGE_API bool get_center(WINDOW_HANDLE wnd, float* center);

LFD_BRIDGE_API bool get_device_name_for_display(unsigned long display_index, int* number_of_device_name_wchars,
                                                wchar_t* device_name);
LFD_BRIDGE_API bool get_device_serial_for_display(unsigned long display_index, int* number_of_serial_wchars,
                                                  wchar_t* serial);
LFD_BRIDGE_API bool get_dimensions_for_display(unsigned long display_index, unsigned long* width,
                                               unsigned long* height);
LFD_BRIDGE_API bool get_window_position_for_display(unsigned long display_index, long* x, long* y);
LFD_BRIDGE_API bool get_device_type_for_display(unsigned long display_index, int* hw_enum);
LFD_BRIDGE_API bool get_calibration_for_display(unsigned long display_index, float* center, float* pitch,
                                                float* slope, int* width, int* height, float* dpi,
                                                float* flip_x, int* invView, float* viewcone, float* fringe,
                                                int* cell_pattern_mode, int* number_of_cells,
                                                CalibrationSubpixelCell* cells);
LFD_BRIDGE_API bool get_invview_for_display(unsigned long display_index, int* invview);
LFD_BRIDGE_API bool get_ri_for_display(unsigned long display_index, int* ri);
LFD_BRIDGE_API bool get_bi_for_display(unsigned long display_index, int* bi);
LFD_BRIDGE_API bool get_tilt_for_display(unsigned long display_index, float* tilt);
LFD_BRIDGE_API bool get_displayaspect_for_display(unsigned long display_index, float* displayaspect);
LFD_BRIDGE_API bool get_fringe_for_display(unsigned long display_index, float* fringe);
LFD_BRIDGE_API bool get_subp_for_display(unsigned long display_index, float* subp);
LFD_BRIDGE_API bool get_viewcone_for_display(unsigned long display_index, float* viewcone);
LFD_BRIDGE_API bool get_pitch_for_display(unsigned long display_index, float* pitch);
LFD_BRIDGE_API bool get_center_for_display(unsigned long display_index, float* center);
LFD_BRIDGE_API bool get_default_quilt_settings_for_display(unsigned long display_index, float* aspect,
                                                           int* quilt_width, int* quilt_height,
                                                           int* quilt_columns, int* quilt_rows);

/* ---- DirectX and Metal: present so every client binds, always false on Linux ------------- */
LFD_BRIDGE_API bool device_from_resource_dx(void* dx_resource, void** dx_device);
LFD_BRIDGE_API bool release_device_dx(void* dx_device);
LFD_BRIDGE_API bool instance_window_dx(void* dx_device, WINDOW_HANDLE* wnd, unsigned long display_index);
LFD_BRIDGE_API bool instance_offscreen_window_dx(void* dx_device, WINDOW_HANDLE* wnd, unsigned long display_index);
LFD_BRIDGE_API bool register_texture_dx(WINDOW_HANDLE wnd, void* dx_texture);
LFD_BRIDGE_API bool unregister_texture_dx(WINDOW_HANDLE wnd, void* dx_texture);
LFD_BRIDGE_API bool save_texture_to_file_dx(WINDOW_HANDLE wnd, wchar_t* filename, void* dx_texture);
LFD_BRIDGE_API bool draw_interop_quilt_texture_dx(WINDOW_HANDLE wnd, void* dx_texture, unsigned long vx,
                                                  unsigned long vy, float aspect, float zoom);
LFD_BRIDGE_API bool draw_interop_rgbd_texture_dx(WINDOW_HANDLE wnd, void* dx_texture, unsigned int width,
                                                 unsigned int height, unsigned int quilt_width,
                                                 unsigned int quilt_height, unsigned int vx, unsigned int vy,
                                                 float focus, float offset, float aspect, float zoom, int depth_loc);
LFD_BRIDGE_API bool create_texture_dx(WINDOW_HANDLE wnd, unsigned long width, unsigned long height, void** dx_texture);
LFD_BRIDGE_API bool release_texture_dx(WINDOW_HANDLE wnd, void* dx_texture);
LFD_BRIDGE_API bool copy_texture_dx(WINDOW_HANDLE wnd, void* src, void* dest);
LFD_BRIDGE_API bool get_offscreen_window_texture_dx(WINDOW_HANDLE wnd, void** dx_texture);
LFD_BRIDGE_API bool instance_window_metal(void* metal_device, WINDOW_HANDLE* wnd, unsigned long display_index);
LFD_BRIDGE_API bool instance_offscreen_window_metal(void* metal_device, WINDOW_HANDLE* wnd,
                                                    unsigned long display_index);
LFD_BRIDGE_API bool create_metal_texture_with_iosurface(WINDOW_HANDLE wnd, void* descriptor, void** texture);
LFD_BRIDGE_API bool copy_metal_texture(WINDOW_HANDLE wnd, void* src, void* dest);
LFD_BRIDGE_API bool release_metal_texture(WINDOW_HANDLE wnd, void* texture);
LFD_BRIDGE_API bool save_metal_texture_to_file(WINDOW_HANDLE wnd, char* filename, void* texture, unsigned int format,
                                               unsigned long width, unsigned long height);
LFD_BRIDGE_API bool draw_interop_quilt_texture_metal(WINDOW_HANDLE wnd, void* texture, unsigned long vx,
                                                     unsigned long vy, float aspect, float zoom);
LFD_BRIDGE_API bool get_offscreen_window_texture_metal(WINDOW_HANDLE wnd, void** texture);

#ifdef __cplusplus
}
#endif

#endif /* LFD_BRIDGE_INPROC_H */
