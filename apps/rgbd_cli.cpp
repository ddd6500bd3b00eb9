#include "apps/rgbd_cli.hpp"

#include <utility>
#include <vector>

namespace lfd::apps {

void RgbdFlags::add(CLI::App& app, const std::string& settings_flag, const std::string& help_prefix) {
  const auto help = [&](const char* text) { return help_prefix + text; };
  app.add_option(settings_flag, settings, help("bridge.js RGBDHologram settings (JSON); flags override"));
  app.add_option("--depth-loc", depth_loc,
                 help("where the depth half is: right (default), left, top, bottom, or bridge.js's 2, 3, 0, 1"));
  app.add_option("--depthiness", depthiness, help("relief scale, 0.1 to 4 (bridge.js default 1.5)"));
  app.add_option("--focus", focus, help("zero-parallax offset, -0.05 to 0.05 (0: mid depth)"));
  app.add_option("--zoom", zoom, help("magnification about the crop centre, 0.1 to 4 (default 1)"));
  app.add_option("--crop-pos-x", crop_x, help("crop centre, half widths, + right, -2 to 2"));
  app.add_option("--crop-pos-y", crop_y, help("crop centre, half heights, + up, -2 to 2"));
  app.add_option("--depth-cutoff", cutoff,
                 help("remove depths farther than this, 0 to 1 on the depth map's scale (1 near; default 0: none)"));
  app.add_flag("--depth-inversion", inversion, help("the depth map has black near (white far)"));
  app.add_flag("--chroma-depth", chroma, help("depth as hue: red near, blue far"));
}

namespace {

std::vector<std::pair<std::string, std::string>> by_key(const RgbdFlags& f) {
  return {{"depth_loc", f.depth_loc},     {"depthiness", f.depthiness}, {"focus", f.focus},
          {"zoom", f.zoom},               {"crop_pos_x", f.crop_x},     {"crop_pos_y", f.crop_y},
          {"depth_cutoff", f.cutoff},
          {"depth_inversion", f.inversion ? "1" : ""}, {"chroma_depth", f.chroma ? "1" : ""}};
}

}  // namespace

bool RgbdFlags::any() const {
  if (!settings.empty()) return true;
  for (const auto& [key, value] : by_key(*this))
    if (!value.empty()) return true;
  return false;
}

rgbd::RgbdOptions RgbdFlags::options() const { return rgbd::rgbd_options_from_command_line(settings, by_key(*this)); }

}  // namespace lfd::apps
