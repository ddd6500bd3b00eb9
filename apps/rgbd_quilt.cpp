// lfd rgbd-quilt: an RGB-D image (colour and depth side by side) to a quilt file that other
// tools (lfd interlace, Looking Glass software) read (docs/rgbd.md).
#include <iostream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "apps/backend.hpp"
#include "apps/cli.hpp"
#include "apps/commands.hpp"
#include "apps/rgbd_cli.hpp"
#include "display/display_quilt.hpp"
#include "interlace/quilt_file_name.hpp"
#include "render/quilt_layout.hpp"
#include "rgbd/gl_rgbd_views.hpp"
#include "rgbd/rgbd_quilt.hpp"
#include "rgbd/rgbd_view_model.hpp"
#include "util/atomic_file.hpp"
#include "util/default_display.hpp"
#include "util/error.hpp"
#include "util/image.hpp"

namespace lfd::apps {

int RunRgbdQuilt(int argc, char** argv) {
  CLI::App app{"Turn an RGB-D image (colour and depth side by side, Looking Glass / bridge.js "
               "conventions) into a quilt by depth-image-based rendering; the file gets a "
               "_qsCxRaA name.\n"
               "\nExamples:\n"
               "  lfd rgbd-quilt photo_rgbd.png photo.png            (depth on the right, 45 views)\n"
               "  lfd rgbd-quilt photo.png out.png --depth-loc left --depthiness 2 --focus 0.01\n"
               "  lfd rgbd-quilt frame.png q.png --calibration visual.json --backend gl\n"
               "  lfd rgbd-quilt frame.png q.png --settings rgbd.json  (bridge.js RGBDHologram settings)",
               "rgbd-quilt"};
  std::string in_path, out_path, backend_name = "cpu";
  RgbdFlags rgbd_flags;
  std::optional<int> views;
  double view_cone_deg = kDefaultViewConeDeg;
  int tile_height = 0;
  app.add_option("rgbd", in_path, "RGB-D image (PNG, JPEG, ...)")->required();
  app.add_option("out", out_path, "quilt file to write (PNG; _qsCxRaA is added)")->required();
  rgbd_flags.add(app, "--settings");
  DisplaySource display;
  display.add(app, "--calibration", "display whose view count and view cone to use", false);
  app.add_option("--views", views, "number of views (default: the display's, else 45)");
  app.add_option("--view-cone", view_cone_deg, "view cone in degrees without a display (default 40)");
  app.add_option("--tile-height", tile_height, "view height in pixels (default: the colour half's)");
  add_backend_option(app, backend_name, "cpu (the reference) or gl (the GL twin, same quilt), auto");
  std::string gl = "auto";
  add_gl_option(app, gl);
  if (auto code = parse(app, argc, argv)) return *code;

  const rgbd::RgbdOptions options = rgbd_flags.options();
  int view_count = views.value_or(kDefaultViewCount);
  std::optional<double> display_aspect;
  if (display.given()) {
    const display::DisplayQuilt quilt = display::quilt_for_display(display.load(), views);
    view_count = quilt.views;
    view_cone_deg = quilt.view_cone_deg;
    display_aspect = quilt.view_aspect;
    std::cout << quilt.describe() << "\n";
  }
  const ImageF frame = to_float(read_image(in_path, 3));
  render::QuiltLayout layout =
      rgbd::rgbd_quilt_layout(frame.width, frame.height, options.depth_loc, view_count, tile_height);
  // Tiles within a pixel of the display's aspect are named with it (no pillarbox column).
  if (display_aspect) layout.aspect = render::snap_to_display_aspect(layout.aspect, layout.tile_height(), *display_aspect);
  const std::string written = interlace::quilt_file_name(out_path, layout, "out");
  const auto gl_context = open_backend(backend_name, true, gl_request(gl));  // the display side: ES will do
  const ImageF quilt = gl_context ? rgbd::render_rgbd_quilt_on_gpu(frame, options, layout, view_cone_deg)
                                  : rgbd::render_rgbd_quilt(frame, options, layout, view_cone_deg);
  write_png(written, to_uint8(quilt));
  std::cout << "wrote " << written << " (" << layout.width << "x" << layout.height << ", "
            << layout.views << " views in " << layout.cols << "x" << layout.rows
            << " tiles, depth at the " << rgbd::depth_location_name(options.depth_loc) << ")\n";
  return 0;
}

}  // namespace lfd::apps
