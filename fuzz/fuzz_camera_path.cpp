// libFuzzer target: `lfd record`'s camera paths (render::parse_camera_path_json: lfd keyframes and
// nerfstudio's camera_path.json) and the cameras sampled from them. Any input must either parse
// or throw lfd::InputError; anything else (a crash, a sanitizer report, another exception) is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "render/camera_path.hpp"
#include "util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const lfd::render::CameraPath path = lfd::render::parse_camera_path_json(text, "fuzz.path.json");
    const double t0 = path.keyframes.front().time_s, d = path.duration_s();
    for (double s : {-0.5, 0.0, 0.3, 0.5, 0.99, 1.0, 2.0}) {
      const lfd::render::CameraSpec spec = path.at(t0 + s * d);
      (void)lfd::render::camera_from_spec(spec, 64, 64);
    }
    (void)lfd::render::parse_camera_path_json(lfd::render::camera_path_json_text(path), "again.json");
  } catch (const lfd::InputError&) {
  }
  return 0;
}
