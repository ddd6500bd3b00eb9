// libFuzzer target: the renderer's cam.json (render::parse_camera_json) and the camera made
// from it. Any input must either parse or throw lfd::InputError; anything else (a crash, a
// sanitizer report, another exception, an allocation beyond -rss_limit_mb) is a bug.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "render/camera_json.hpp"
#include "util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const lfd::render::CameraSpec spec = lfd::render::parse_camera_json(text, "fuzz.cam.json");
    (void)lfd::render::camera_from_spec(spec, spec.width ? std::nullopt : std::optional<int>(64),
                                        spec.height ? std::nullopt : std::optional<int>(64));
  } catch (const lfd::InputError&) {
  }
  return 0;
}
