// libbridge_inproc's parts without GL or a window (docs/bridge-inproc.md): the HoloPlay values
// against the published test vector, the C API's strings, the vendor clients' settings files, the
// drawing thread's newest-frame rule.
#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <future>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bridge_inproc/bridge_log.hpp"
#include "bridge_inproc/bridge_registration.hpp"
#include "bridge_inproc/bridge_settings.hpp"
#include "bridge_inproc/gl_thread.hpp"
#include "bridge_inproc/holoplay_values.hpp"
#include "bridge_inproc/wide_text.hpp"
#include "display/calibration_file.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"

namespace fs = std::filesystem;
using namespace lfd;
using namespace lfd::bridge;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("lfd_bridge_parts_" + name + "_" + std::to_string(getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

}  // namespace

// docs/display-model.md, "The test vector": LKG-APW92011's shader values as
// sgumhold/cgv publishes them.
TEST(HoloPlayValues, MatchThePublishedShaderValuesOfLkgApw92011) {
  const display::Calibration c =
      display::read_calibration(fs::path(LFD_TEST_DATA_DIR) / "calibrations" / "LKG-APW92011.visual.json");
  const HoloPlayValues v = holoplay_values(c.display);
  EXPECT_NEAR(v.pitch, 673.46088569750157, 1e-3);
  EXPECT_NEAR(v.tilt, -0.074780801514116493, 1e-7);
  EXPECT_NEAR(v.subp, 1.0 / (3 * 3840), 1e-10);
  EXPECT_FLOAT_EQ(v.center, float(c.display.center_periods));  // raw
  EXPECT_FLOAT_EQ(v.displayaspect, 3840.f / 2160.f);
  EXPECT_EQ(v.ri, 0);
  EXPECT_EQ(v.bi, 2);
}

TEST(HoloPlayValues, FlipSubpSwapsTheRedAndBlueIndex) {
  display::DisplayCalibration d;
  d.flip_subp = true;
  const HoloPlayValues v = holoplay_values(d);
  EXPECT_EQ(v.ri, 2);
  EXPECT_EQ(v.bi, 0);
}

TEST(WideText, ReadsCharAndWcharStrings) {
  EXPECT_EQ(text_of_c_or_wide("visual.json", "path"), "visual.json");
  EXPECT_EQ(text_of_c_or_wide(L"visual.json", "path"), "visual.json");
  EXPECT_EQ(text_of_c_or_wide(L"caf\u00e9", "name"), "caf\xc3\xa9");  // UTF-8 of a wide string
  EXPECT_THROW(text_of_c_or_wide(nullptr, "path"), BadCall);
  EXPECT_THROW(text_of_c_or_wide("", "path"), BadCall);
  const std::string long_text(5000, 'a');
  EXPECT_THROW(text_of_c_or_wide(long_text.c_str(), "path"), BadCall);
}

TEST(WideText, WritesInTwoCallsWithTheTerminatorCounted) {
  int count = 0;
  write_wide("LKG-PORT", &count, nullptr);
  EXPECT_EQ(count, 9);
  std::vector<wchar_t> buf(size_t(count), L'x');
  write_wide("LKG-PORT", &count, buf.data());
  EXPECT_EQ(std::wstring(buf.data()), L"LKG-PORT");
  count = 4;  // a short buffer is filled and terminated, never overrun
  std::vector<wchar_t> small(4, L'x');
  write_wide("LKG-PORT", &count, small.data());
  EXPECT_EQ(std::wstring(small.data()), L"LKG");
  EXPECT_THROW(write_wide("x", nullptr, nullptr), BadCall);
}

TEST(Registration, KeepsForeignEntriesAndKeysAndRemovesOnlyLfds) {
  const fs::path home = fresh_dir("home");
  const RegistrationFiles files = registration_files(home);
  write_text_atomic(files.python_settings,
                    R"({"enable_utilization_telemetry": true, "install_locations": [{"version": "2.6.0", "path": "/opt/b"}]})");
  write_text_atomic(files.legacy_list, "/opt/Bridge-2.5.0\n");
  const fs::path lib = fresh_dir("lib") / library_folder_name();
  fs::create_directories(lib);
  std::ofstream(lib / "libbridge_inproc.so") << "x";
  register_library(files, lib);
  register_library(files, lib);  // twice: still one entry of lfd's
  const auto py = nlohmann::json::parse(read_text_file(files.python_settings));
  EXPECT_EQ(py["enable_utilization_telemetry"], true);
  ASSERT_EQ(py["install_locations"].size(), 2u);
  EXPECT_EQ(py["install_locations"][0]["path"], "/opt/b");
  EXPECT_EQ(py["install_locations"][1]["version"], bridge_version_text());
  EXPECT_EQ(read_text_file(files.legacy_list), "/opt/Bridge-2.5.0\n" + lib.string() + "\n");
  int lfd_entries = 0;
  for (const RegisteredEntry& e : registered_entries(files)) lfd_entries += e.lfd && e.library_present;
  EXPECT_EQ(lfd_entries, 3);
  EXPECT_EQ(unregister_library(files), 3);
  EXPECT_EQ(nlohmann::json::parse(read_text_file(files.python_settings))["install_locations"].size(), 1u);
  EXPECT_EQ(read_text_file(files.legacy_list), "/opt/Bridge-2.5.0\n");
  EXPECT_EQ(nlohmann::json::parse(read_text_file(files.native_settings))["install_locations"].size(), 0u);
}

TEST(Registration, LeavesAFileThatIsNotJsonAsItIs) {
  const fs::path home = fresh_dir("bad");
  const RegistrationFiles files = registration_files(home);
  write_text_atomic(files.native_settings, "{not json");
  const fs::path lib = fresh_dir("lib2") / library_folder_name();
  fs::create_directories(lib);
  std::ofstream(lib / "libbridge_inproc.so") << "x";
  EXPECT_THROW(register_library(files, lib), InputError);
  EXPECT_EQ(read_text_file(files.native_settings), "{not json");
  EXPECT_FALSE(fs::exists(files.python_settings));  // nothing half done
}

TEST(LfdSettings, RoundTripAndBadFieldsNamed) {
  const fs::path dir = fresh_dir("settings");
  LfdBridgeSettings s;
  s.calibrations = {"/a/visual.json"};
  s.device = "";
  s.monitor = "HDMI";
  s.gl = "es";
  write_lfd_settings(dir / "bridge.json", s);
  const LfdBridgeSettings back = read_lfd_settings(dir / "bridge.json");
  EXPECT_EQ(back.calibrations, s.calibrations);
  EXPECT_EQ(back.device, "");
  EXPECT_EQ(back.monitor, "HDMI");
  EXPECT_EQ(back.gl, "es");
  EXPECT_EQ(read_lfd_settings(dir / "absent.json").device, "auto");
  EXPECT_EQ(read_lfd_settings(dir / "absent.json").gl, "auto");
  EXPECT_THROW(parse_lfd_settings(R"({"calibrations": "x"})", "f"), InputError);
  EXPECT_THROW(parse_lfd_settings(R"({"device": 3})", "f"), InputError);
  try {
    parse_lfd_settings(R"({"gl": "vulkan"})", "f.json");
    ADD_FAILURE() << "a gl that is not auto, desktop or es was taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("f.json: gl: 'vulkan'"), std::string::npos) << e.what();
  }
}

// docs/arm.md: the library's contexts follow LFD_GL when it is set, else the settings' "gl".
TEST(LfdSettings, LfdGlOverridesTheSettingsGl) {
  const char* saved = std::getenv("LFD_GL");
  const std::string before = saved ? saved : "";
  LfdBridgeSettings s;
  s.gl = "es";
  unsetenv("LFD_GL");
  EXPECT_EQ(library_gl_request(s), gpu::GlRequest::kEs);
  setenv("LFD_GL", "desktop", 1);
  EXPECT_EQ(library_gl_request(s), gpu::GlRequest::kDesktop);
  setenv("LFD_GL", "", 1);
  EXPECT_EQ(library_gl_request(s), gpu::GlRequest::kEs);
  setenv("LFD_GL", "metal", 1);
  EXPECT_THROW(library_gl_request(s), InputError);
  if (saved) setenv("LFD_GL", before.c_str(), 1); else unsetenv("LFD_GL");
}

TEST(GlThread, TheNewestWaitingFrameReplacesAnOlderOne) {
  GlThread thread;
  std::promise<void> release;
  std::shared_future<void> gate = release.get_future().share();
  std::atomic<int> ran{0}, last{0};
  thread.post(0, "block", [gate] { gate.wait(); });  // holds the thread while frames queue
  for (int frame = 1; frame <= 5; ++frame)
    thread.post(7, "frame", [&, frame] {
      ++ran;
      last = frame;
    });
  release.set_value();
  thread.call([] {});  // after everything queued before it
  EXPECT_EQ(ran.load(), 1);
  EXPECT_EQ(last.load(), 5);
  EXPECT_THROW(thread.call([]() -> int { throw BadCall("refused"); }), BadCall);
}
