/* A C client of libbridge_inproc (docs/bridge-inproc.md "Tests"), built against bridge_inproc.h and
 * linked with the library as the vendor's native clients are: every exported function is called
 * (so a missing one fails the link), the bad calls must return false with the process alive, and
 * a quilt texture of a GLFW (GLX) context is drawn into a window on the screen, which is read back
 * (XGetImage of the root window) and compared with the panel `lfd interlace` wrote.
 *
 *   bridge_c_client CALIBRATION.json QUILT.png COLS ROWS ASPECT PANEL.png OUT_DIR
 *
 * Prints "PSNR <dB>" lines and exits 0 only when every check passed. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <wchar.h>

#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <epoxy/gl.h>
#include <GLFW/glfw3.h>
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>

#include "bridge_inproc/bridge_inproc.h"

static int failures = 0;

#define CHECK(cond)                                                \
  do {                                                             \
    if (!(cond)) {                                                 \
      fprintf(stderr, "FAILED %s:%d: %s\n", __FILE__, __LINE__, #cond); \
      ++failures;                                                  \
    }                                                              \
  } while (0)

static void sleep_ms(int ms) {
  struct timespec t = {ms / 1000, (ms % 1000) * 1000000L};
  nanosleep(&t, NULL);
}

/* RGB rows top-down of an image file. */
static unsigned char* load_rgb(const char* path, int* w, int* h) {
  int n = 0;
  unsigned char* p = stbi_load(path, w, h, &n, 3);
  if (!p) {
    fprintf(stderr, "cannot read %s\n", path);
    exit(2);
  }
  return p;
}

static double psnr(const unsigned char* a, const unsigned char* b, size_t n) {
  double se = 0;
  for (size_t i = 0; i < n; ++i) {
    const double d = (double)a[i] - (double)b[i];
    se += d * d;
  }
  if (se == 0) return 99.0;
  return 10.0 * log10(255.0 * 255.0 / (se / (double)n));
}

/* The screen's top-left w x h as RGB rows top-down. */
static void grab_screen(Display* x, int w, int h, unsigned char* out) {
  XImage* image = XGetImage(x, DefaultRootWindow(x), 0, 0, (unsigned)w, (unsigned)h, AllPlanes, ZPixmap);
  for (int y = 0; y < h; ++y)
    for (int i = 0; i < w; ++i) {
      const unsigned long p = XGetPixel(image, i, y);
      unsigned char* o = out + ((size_t)y * w + i) * 3;
      o[0] = (unsigned char)((p & image->red_mask) >> 16);
      o[1] = (unsigned char)((p & image->green_mask) >> 8);
      o[2] = (unsigned char)(p & image->blue_mask);
    }
  XDestroyImage(image);
}

/* A GL texture of the current context from RGB rows top-down (GL rows bottom-up). */
static GLuint make_texture(const unsigned char* rgb, int w, int h) {
  unsigned char* rgba = malloc((size_t)w * h * 4);
  for (int y = 0; y < h; ++y)
    for (int i = 0; i < w; ++i) {
      const unsigned char* s = rgb + ((size_t)(h - 1 - y) * w + i) * 3;
      unsigned char* d = rgba + ((size_t)y * w + i) * 4;
      d[0] = s[0];
      d[1] = s[1];
      d[2] = s[2];
      d[3] = 255;
    }
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  free(rgba);
  return t;
}

static void check_getters(WINDOW_HANDLE wnd, unsigned long display) {
  float f = 0, aspect = 0;
  int i = 0, qw = 0, qh = 0, qc = 0, qr = 0;
  unsigned long uw = 0, uh = 0;
  long x = -1, y = -1;
  float center, pitch, slope, dpi, flip_x, viewcone, fringe;
  int width, height, inv_view, mode, cells = 0;
  CHECK(get_calibration(wnd, &center, &pitch, &slope, &width, &height, &dpi, &flip_x, &inv_view, &viewcone, &fringe,
                        &mode, &cells, NULL));
  CHECK(width > 0 && height > 0 && pitch > 0);
  if (cells > 0) {
    CalibrationSubpixelCell* buf = calloc((size_t)cells, sizeof *buf);
    CHECK(get_calibration(wnd, &center, &pitch, &slope, &width, &height, &dpi, &flip_x, &inv_view, &viewcone, &fringe,
                          &mode, &cells, buf));
    free(buf);
  }
  CHECK(get_calibration_for_display(display, &center, &pitch, &slope, &width, &height, &dpi, &flip_x, &inv_view,
                                    &viewcone, &fringe, &mode, &cells, NULL));
  int n = 0;
  CHECK(get_device_name(wnd, &n, NULL) && n > 1);
  wchar_t name[256];
  n = 256;
  CHECK(get_device_name(wnd, &n, name) && wcslen(name) > 0);
  n = 0;
  CHECK(get_device_serial(wnd, &n, NULL) && n >= 1);
  n = 256;
  CHECK(get_device_serial(wnd, &n, name));
  n = 0;
  CHECK(get_device_name_for_display(display, &n, NULL) && n > 1);
  n = 256;
  CHECK(get_device_serial_for_display(display, &n, name));
  CHECK(get_device_type(wnd, &i));
  CHECK(get_device_type_for_display(display, &i));
  CHECK(get_default_quilt_settings(wnd, &aspect, &qw, &qh, &qc, &qr) && qc > 0 && qr > 0 && aspect > 0);
  CHECK(get_default_quilt_settings_for_display(display, &aspect, &qw, &qh, &qc, &qr));
  CHECK(get_viewcone(wnd, &f) && f > 0);
  CHECK(get_invview(wnd, &i));
  CHECK(get_ri(wnd, &i) && (i == 0 || i == 2));
  CHECK(get_bi(wnd, &i) && (i == 0 || i == 2));
  CHECK(get_tilt(wnd, &f));
  CHECK(get_displayaspect(wnd, &f) && fabsf(f - (float)width / (float)height) < 1e-5f);
  CHECK(get_fringe(wnd, &f));
  CHECK(get_subp(wnd, &f) && fabsf(f - 1.0f / (3.0f * (float)width)) < 1e-9f);
  CHECK(get_pitch(wnd, &f) && f > 0);
  CHECK(get_center(wnd, &f) && f == center);
  CHECK(get_invview_for_display(display, &i));
  CHECK(get_ri_for_display(display, &i));
  CHECK(get_bi_for_display(display, &i));
  CHECK(get_tilt_for_display(display, &f));
  CHECK(get_displayaspect_for_display(display, &f));
  CHECK(get_fringe_for_display(display, &f));
  CHECK(get_subp_for_display(display, &f));
  CHECK(get_viewcone_for_display(display, &f));
  CHECK(get_pitch_for_display(display, &f));
  CHECK(get_center_for_display(display, &f));
  CHECK(get_dimensions_for_display(display, &uw, &uh) && (int)uw == width && (int)uh == height);
  CHECK(get_window_position_for_display(display, &x, &y));
  CHECK(get_window_dimensions(wnd, &uw, &uh) && (int)uw == width && (int)uh == height);
  CHECK(get_window_position(wnd, &x, &y));
  CHECK(get_max_texture_size(wnd, &uw) && uw >= 2048);
  CHECK(get_display_for_window(wnd, &uw) && uw == display);
}

/* Every refusal the issue lists: false, and the process goes on. */
static void check_bad_calls(WINDOW_HANDLE wnd, GLuint texture, GLuint deleted, int w, int h, int cols, int rows,
                            float aspect) {
  unsigned long ul = 0;
  float f = 0;
  int n = 0;
  WINDOW_HANDLE other = 0;
  CHECK(!draw_interop_quilt_texture_gl(987654, texture, LFD_BRIDGE_RGBA, w, h, cols, rows, aspect, 1));
  CHECK(!draw_interop_quilt_texture_gl(wnd, 0, LFD_BRIDGE_RGBA, w, h, cols, rows, aspect, 1));
  CHECK(!draw_interop_quilt_texture_gl(wnd, deleted, LFD_BRIDGE_RGBA, w, h, cols, rows, aspect, 1));
  CHECK(!draw_interop_quilt_texture_gl(wnd, texture, LFD_BRIDGE_RGBA_DXT5, w, h, cols, rows, aspect, 1));
  CHECK(!draw_interop_quilt_texture_gl(wnd, texture, LFD_BRIDGE_NO_FORMAT, w, h, cols, rows, aspect, 1));
  CHECK(!draw_interop_quilt_texture_gl(wnd, texture, LFD_BRIDGE_RGBA, 0, h, cols, rows, aspect, 1));
  CHECK(!draw_interop_quilt_texture_gl(wnd, texture, LFD_BRIDGE_RGBA, w, h, 0, rows, aspect, 1));
  CHECK(!draw_interop_quilt_texture_gl(wnd, texture, LFD_BRIDGE_RGBA, w, h, cols, 0, aspect, 1));
  CHECK(!draw_interop_quilt_texture_gl(wnd, texture, LFD_BRIDGE_RGBA, w + 1, h, cols, rows, aspect, 1));
  CHECK(!draw_interop_quilt_texture_gl(wnd, texture, LFD_BRIDGE_RGBA, w, h, cols, rows, 0.0f, 1));
  CHECK(!draw_interop_quilt_texture_gl(wnd, texture, LFD_BRIDGE_RGBA, w, h, cols, rows, NAN, 1));
  CHECK(!set_interop_quilt_texture_gl(wnd, 0, LFD_BRIDGE_RGBA, w, h, cols, rows, aspect, 1));
  CHECK(!draw_interop_rgbd_texture_gl(wnd, texture, LFD_BRIDGE_RGBA, w, h, w, h, cols, rows, aspect, 0, 1, 1, 7));
  CHECK(!draw_interop_rgbd_texture_gl(wnd, 0, LFD_BRIDGE_RGBA, w, h, w, h, cols, rows, aspect, 0, 1, 1, 2));
  CHECK(!get_window_dimensions(wnd, NULL, &ul));
  CHECK(!get_window_dimensions(424242, &ul, &ul));
  CHECK(!get_viewcone(wnd, NULL));
  CHECK(!get_pitch(0, &f));
  CHECK(!get_device_name(wnd, NULL, NULL));
  CHECK(!get_displays(NULL, NULL));
  CHECK(!get_pitch_for_display(99, &f));
  CHECK(!get_calibration(wnd, NULL, &f, &f, &n, &n, &f, &f, &n, &f, &f, &n, &n, NULL));
  CHECK(!instance_window_gl(NULL, 0));
  CHECK(!instance_window_gl(&other, 7));
  CHECK(!instance_offscreen_window(&other, 64, 64, L"/nonexistent/visual.json"));
  CHECK(!instance_offscreen_window(&other, 0, 64, L"/nonexistent/visual.json"));
  CHECK(!instance_offscreen_window(&other, 64, 64, NULL));
  CHECK(!show_window(31337, true));
  CHECK(!save_texture_to_file_gl(wnd, NULL, texture, LFD_BRIDGE_RGBA, w, h));
  CHECK(!save_image_to_file(wnd, "/tmp/never.png", NULL, LFD_BRIDGE_RGB, 4, 4));
  CHECK(!quiltify_rgbd(wnd, 0, 6, 48, 0.75f, 1, 1, 14, 0, 0, 0, 0, 2, 1, 0, 0, L"/nonexistent.png", L"/tmp/q.png"));
  CHECK(!quiltify_rgbd(wnd, 8, 6, 48, 0.75f, 1, 1, 14, 0, 0, 0, 0, 2, 1, 0, 0, L"/nonexistent.png", L"/tmp/q.png"));
  CHECK(!get_offscreen_window_texture_gl(wnd, NULL, NULL, NULL, NULL));
  /* DirectX and Metal: present, false. */
  void* p = NULL;
  CHECK(!device_from_resource_dx(NULL, &p));
  CHECK(!release_device_dx(NULL));
  CHECK(!instance_window_dx(NULL, &other, 0));
  CHECK(!instance_offscreen_window_dx(NULL, &other, 0));
  CHECK(!register_texture_dx(wnd, NULL));
  CHECK(!unregister_texture_dx(wnd, NULL));
  CHECK(!save_texture_to_file_dx(wnd, NULL, NULL));
  CHECK(!draw_interop_quilt_texture_dx(wnd, NULL, 1, 1, 1, 1));
  CHECK(!draw_interop_rgbd_texture_dx(wnd, NULL, 1, 1, 1, 1, 1, 1, 0, 0, 1, 1, 0));
  CHECK(!create_texture_dx(wnd, 1, 1, &p));
  CHECK(!release_texture_dx(wnd, NULL));
  CHECK(!copy_texture_dx(wnd, NULL, NULL));
  CHECK(!get_offscreen_window_texture_dx(wnd, &p));
  CHECK(!instance_window_metal(NULL, &other, 0));
  CHECK(!instance_offscreen_window_metal(NULL, &other, 0));
  CHECK(!create_metal_texture_with_iosurface(wnd, NULL, &p));
  CHECK(!copy_metal_texture(wnd, NULL, NULL));
  CHECK(!release_metal_texture(wnd, NULL));
  CHECK(!save_metal_texture_to_file(wnd, NULL, NULL, LFD_BRIDGE_RGBA, 1, 1));
  CHECK(!draw_interop_quilt_texture_metal(wnd, NULL, 1, 1, 1, 1));
  CHECK(!get_offscreen_window_texture_metal(wnd, &p));
}

int main(int argc, char** argv) {
  if (argc != 8) {
    fprintf(stderr, "usage: bridge_c_client CALIBRATION QUILT COLS ROWS ASPECT PANEL OUT_DIR\n");
    return 2;
  }
  const char* calibration = argv[1];
  const int cols = atoi(argv[3]), rows = atoi(argv[4]);
  const float aspect = (float)atof(argv[5]);
  const char* out_dir = argv[7];

  /* lfd's bridge settings: this calibration, no device discovery. */
  char config[4096];
  snprintf(config, sizeof config, "%s/bridge.json", out_dir);
  FILE* f = fopen(config, "w");
  fprintf(f, "{\"calibrations\": [\"%s\"], \"device\": \"\"}\n", calibration);
  fclose(f);
  setenv("LFD_BRIDGE_CONFIG", config, 1);

  int count = 0;
  CHECK(!get_displays(&count, NULL)); /* before initialize_bridge */
  CHECK(!instance_window_gl(&(WINDOW_HANDLE){0}, LFD_BRIDGE_FIRST_LOOKING_GLASS_DEVICE));

  /* The client's own GL context: a hidden GLFW window, as the Python SDK's examples make. */
  CHECK(glfwInit());
  glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
  GLFWwindow* own = glfwCreateWindow(16, 16, "client", NULL, NULL);
  CHECK(own != NULL);
  glfwMakeContextCurrent(own);

  CHECK(initialize_bridge("bridge_c_client"));
  unsigned long major = 0, minor = 0, build = 0;
  int postfix_count = 0;
  CHECK(get_bridge_version(&major, &minor, &build, &postfix_count, NULL) && postfix_count > 1);
  wchar_t postfix[64];
  postfix_count = 64;
  CHECK(get_bridge_version(&major, &minor, &build, &postfix_count, postfix));
  CHECK(major == 2 && minor == 6);
  CHECK(get_displays(&count, NULL) && count == 1);
  unsigned long displays[4] = {99, 99, 99, 99};
  count = 4;
  CHECK(get_displays(&count, displays) && count == 1 && displays[0] == 0);

  WINDOW_HANDLE wnd = 0;
  CHECK(instance_window_gl(&wnd, LFD_BRIDGE_FIRST_LOOKING_GLASS_DEVICE) && wnd != 0);
  CHECK(show_window(wnd, true));
  check_getters(wnd, 0);

  int qw = 0, qh = 0, pw = 0, ph = 0;
  unsigned char* quilt = load_rgb(argv[2], &qw, &qh);
  unsigned char* panel = load_rgb(argv[6], &pw, &ph);
  const GLuint texture = make_texture(quilt, qw, qh);
  GLuint deleted = make_texture(quilt, 4, 4);
  glDeleteTextures(1, &deleted);
  GLint bound_before = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound_before);

  CHECK(set_interop_quilt_texture_gl(wnd, texture, LFD_BRIDGE_RGBA, qw, qh, cols, rows, aspect, 1.0f));
  CHECK(draw_interop_quilt_texture_gl(wnd, texture, LFD_BRIDGE_RGBA, qw, qh, cols, rows, aspect, 1.0f));
  GLint bound_after = -1;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound_after);
  CHECK(bound_after == bound_before); /* the caller's binding is left as it was */
  CHECK(glfwGetCurrentContext() == own);

  /* The screen, read back until the frame is there (the drawing thread swaps on its own). */
  Display* x = XOpenDisplay(NULL);
  unsigned char* screen = malloc((size_t)pw * ph * 3);
  double best = 0;
  for (int attempt = 0; attempt < 60 && best < 40; ++attempt) {
    sleep_ms(500);
    grab_screen(x, pw, ph, screen);
    best = psnr(screen, panel, (size_t)pw * ph * 3);
  }
  printf("PSNR screen-vs-lfd-interlace (GLFW/GLX texture) %.2f\n", best);
  CHECK(best >= 40.0);

  check_bad_calls(wnd, texture, deleted, qw, qh, cols, rows, aspect);

  /* The offscreen window of the same display, read back through the caller's context. */
  WINDOW_HANDLE off = 0;
  CHECK(instance_offscreen_window_gl(&off, 0) && off != 0 && off != wnd);
  CHECK(draw_interop_quilt_texture_gl(off, texture, LFD_BRIDGE_RGBA, qw, qh, cols, rows, aspect, 1.0f));
  unsigned long long off_texture = 0;
  unsigned int format = 0;
  unsigned long ow = 0, oh = 0;
  CHECK(get_offscreen_window_texture_gl(off, &off_texture, &format, &ow, &oh));
  CHECK((int)ow == pw && (int)oh == ph && format == LFD_BRIDGE_RGBA && off_texture != 0);
  char path[4200];
  snprintf(path, sizeof path, "%s/offscreen_panel.png", out_dir);
  CHECK(save_texture_to_file_gl(off, path, off_texture, LFD_BRIDGE_RGBA, ow, oh));
  int sw = 0, sh = 0;
  unsigned char* saved = load_rgb(path, &sw, &sh);
  const double off_psnr = psnr(saved, panel, (size_t)pw * ph * 3);
  printf("PSNR offscreen-texture-vs-lfd-interlace %.2f\n", off_psnr);
  CHECK(sw == pw && sh == ph && off_psnr >= 40.0);

  WINDOW_HANDLE from_file = 0;
  wchar_t wide_path[4096];
  mbstowcs(wide_path, calibration, 4096);
  CHECK(instance_offscreen_window(&from_file, (unsigned long)pw, (unsigned long)ph, wide_path));
  unsigned long ignored = 0;
  CHECK(!get_display_for_window(from_file, &ignored)); /* made from a file, not a display */

  snprintf(path, sizeof path, "%s/image.png", out_dir);
  unsigned char pixels[4 * 4 * 3] = {0};
  CHECK(save_image_to_file(wnd, path, pixels, LFD_BRIDGE_RGB, 4, 4));
  CHECK(show_window(wnd, false));
  CHECK(show_window(wnd, true));

  CHECK(uninitialize_bridge());
  CHECK(uninitialize_bridge()); /* twice is fine */
  CHECK(!get_pitch(wnd, &(float){0})); /* after: the windows are gone */
  CHECK(glfwGetCurrentContext() == own);
  glfwDestroyWindow(own);
  glfwTerminate();
  XCloseDisplay(x);
  free(screen);
  stbi_image_free(quilt);
  stbi_image_free(panel);
  stbi_image_free(saved);
  printf("%s\n", failures ? "FAILED" : "OK");
  return failures ? 1 : 0;
}
