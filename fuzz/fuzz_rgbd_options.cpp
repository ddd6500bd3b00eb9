// libFuzzer target: the RGB-D options (rgbd/rgbd_options.hpp): bridge.js settings JSON when the
// input starts with '{', else "key=value" lines through set_rgbd_option (the command line's
// path). Any input must either parse or throw lfd::InputError; what parses must pass check()
// and come back the same through rgbd_options_to_json. Anything else is a bug.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "rgbd/rgbd_options.hpp"
#include "util/error.hpp"

namespace {

lfd::rgbd::RgbdOptions parse(std::string_view text) {
  if (!text.empty() && text.front() == '{') return lfd::rgbd::parse_rgbd_options_json(text);
  lfd::rgbd::RgbdOptions options;
  while (!text.empty()) {
    const size_t end = text.find('\n');
    const std::string_view line = text.substr(0, end);
    const size_t eq = line.find('=');
    if (eq != std::string_view::npos)
      lfd::rgbd::set_rgbd_option(options, line.substr(0, eq), line.substr(eq + 1));
    text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
  }
  return options;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const lfd::rgbd::RgbdOptions o = parse(text);
    o.check();
    const lfd::rgbd::RgbdOptions back =
        lfd::rgbd::rgbd_options_from_json(lfd::rgbd::rgbd_options_to_json(o));
    if (back.depth_loc != o.depth_loc || back.depthiness != o.depthiness || back.focus != o.focus ||
        back.zoom != o.zoom || back.crop_pos_x != o.crop_pos_x ||
        back.crop_pos_y != o.crop_pos_y || back.depth_inversion != o.depth_inversion ||
        back.chroma_depth != o.chroma_depth)
      std::abort();  // the round trip lost a value
  } catch (const lfd::InputError&) {
  }
  return 0;
}
