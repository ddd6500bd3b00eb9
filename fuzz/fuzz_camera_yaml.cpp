// libFuzzer target: camera intrinsics in OpenCV FileStorage YAML (sim::CameraIntrinsics::
// read_yaml, the file `--camera C.yaml` takes). The reader takes a path, so each input is
// written to a scratch file first (FileStorage recognises YAML, XML and JSON by content, so
// all three of OpenCV's parsers are reached). Any input must either parse or throw
// lfd::InputError; anything else (a crash, a sanitizer report, a cv::Exception, an allocation
// beyond -rss_limit_mb) is a bug.
#include <cstddef>
#include <cstdint>

#include "sim/camera_model.hpp"
#include "fuzz/fuzz_input_file.hpp"
#include "util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto path = lfd::fuzz::write_input("camera.yaml", data, size);
  try {
    (void)lfd::sim::CameraIntrinsics::read_yaml(path);
  } catch (const lfd::InputError&) {
  }
  return 0;
}
