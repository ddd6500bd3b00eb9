// libFuzzer target: the capture manifest DIR/patterns/manifest.json that `lfd patterns` writes
// and `lfd calibrate` reads (sim::read_pattern_set, with its nominal calibration). The
// reader takes a folder, so each input is written to a scratch folder's patterns/manifest.json.
// Any input must either parse or throw lfd::InputError; anything else (a crash, a sanitizer
// report, another exception, an allocation beyond -rss_limit_mb) is a bug.
#include <cstddef>
#include <cstdint>

#include "sim/patterns.hpp"
#include "fuzz/fuzz_input_file.hpp"
#include "util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  lfd::fuzz::write_input("capture/patterns/manifest.json", data, size);
  try {
    (void)lfd::sim::read_pattern_set(lfd::fuzz::scratch_dir() / "capture");
  } catch (const lfd::InputError&) {
  }
  return 0;
}
