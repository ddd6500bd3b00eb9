// The whole discovery on fakes: a Gen1 unit behind a fake HID transport, volumes in a tree under
// --root, DRM connectors with EDIDs; choosing a device by serial or "auto" and the messages when
// none, several, or only unreadable ones are found; unreadable USB units explained.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "device/device_discovery.hpp"
#include "device/device_error.hpp"
#include "display/visual_json.hpp"
#include "tests/device/device_test_tree.hpp"
#include "tests/device/fake_holoplay.hpp"
#include "tests/test_data.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"
#include "util/error.hpp"

namespace lfd::device {
namespace {

namespace fs = std::filesystem;

std::string text_of(const std::string& name) { return read_text_file(test::fixture_calibration(name)); }

// Discovery options with one fake Gen1 unit (or none) and no real USB.
struct FakeMachine {
  fs::path root;
  test::FakeClock clock;
  std::vector<std::string> eeproms;  // one fake HoloPlay per text
  std::function<void(test::FakeHoloPlay&)> fault = [](test::FakeHoloPlay&) {};
  UsbEnumeration usb;

  DiscoveryOptions options() {
    DiscoveryOptions o;
    o.root = root;
    o.gen1.clock = clock.fn();
    o.enumerate_hid = [this] {
      std::vector<HidDeviceInfo> list;
      for (size_t i = 0; i < eeproms.size(); ++i) {
        HidDeviceInfo info;
        info.path = "/dev/hidraw";
        info.path += std::to_string(i);
        info.product = kGen1Product;
        info.vendor_id = kGen1VendorId;
        info.product_id = kGen1ProductId;
        list.push_back(info);
      }
      HidDeviceInfo other;  // the same Microchip IDs on another product: not ours
      other.path = "/dev/hidraw9";
      other.product = "PICkit";
      other.vendor_id = kGen1VendorId;
      other.product_id = kGen1ProductId;
      list.push_back(other);
      return list;
    };
    o.open_hid = [this](const HidDeviceInfo& info) -> std::unique_ptr<HidTransport> {
      const size_t i = std::stoul(info.path.substr(11));
      auto device = std::make_unique<test::FakeHoloPlay>(test::eeprom_image(eeproms.at(i)), clock);
      fault(*device);
      return device;
    };
    o.enumerate_usb = [this] { return usb; };
    return o;
  }
};

TEST(DeviceDiscovery, FindsAGen1UnitAndAVolumeAndReadsBoth) {
  FakeMachine m;
  m.root = test::temp_dir("disc_both");
  m.eeproms = {text_of("LKG-2K-04409.visual.json")};
  test::put_calibration(m.root, "/media/me/LKG-A", text_of("LKG-APW92011.visual.json"));
  const Discovery found = discover_devices(m.options());
  ASSERT_EQ(found.devices.size(), 2u);
  EXPECT_EQ(found.devices[0].kind, DeviceKind::kGen1Hid);
  EXPECT_EQ(found.devices[0].serial, "LKG-2K-04409");
  EXPECT_EQ(found.devices[0].source, "/dev/hidraw0");
  EXPECT_EQ(found.devices[0].visual_json, text_of("LKG-2K-04409.visual.json"));
  EXPECT_EQ(found.devices[0].screen_w, 2560);
  EXPECT_EQ(found.devices[1].kind, DeviceKind::kUsbVolume);
  EXPECT_EQ(found.devices[1].serial, "LKG-APW92011");

  EXPECT_EQ(&select_device(found, "lkg-apw92011"), &found.devices[1]);
  EXPECT_EQ(&select_device(found, "LKG-2K-04409"), &found.devices[0]);
  try {
    select_device(found, "auto");
    FAIL() << "two units: auto must refuse";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--device SERIAL"), std::string::npos) << e.what();
  }
}

TEST(DeviceDiscovery, TheCalibrationOfADeviceEqualsTheServedOne) {
  FakeMachine m;
  m.root = test::temp_dir("disc_cal");
  m.eeproms = {text_of("gen1-hid-00297.visual.json")};
  const display::Calibration c = read_device_calibration("auto", m.options());
  const display::DisplayCalibration served =
      display::parse_visual_json(text_of("gen1-hid-00297.visual.json"), "served");
  EXPECT_EQ(c.display.serial, served.serial);
  EXPECT_EQ(c.display.pitch_lpi, served.pitch_lpi);
  EXPECT_EQ(c.display.slope, served.slope);
  EXPECT_EQ(c.display.center_periods, served.center_periods);
  EXPECT_EQ(display::to_visual_json(c.display), display::to_visual_json(served));
  EXPECT_EQ(c.provenance["device"]["source"], "/dev/hidraw0");
}

TEST(DeviceDiscovery, NothingFoundSaysWhatWasSearchedAndWhatToDo) {
  FakeMachine m;
  m.root = test::temp_dir("disc_none");
  m.usb.problem = "libusb cannot enumerate the USB bus";
  const Discovery found = discover_devices(m.options());
  EXPECT_TRUE(found.devices.empty());
  try {
    select_device(found, "auto");
    FAIL();
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("no Looking Glass found"), std::string::npos);
    EXPECT_NE(message.find("--calibration"), std::string::npos);
    EXPECT_NE(message.find("libusb cannot enumerate"), std::string::npos);
    EXPECT_EQ(message.find('\n'), std::string::npos);
  }
}

TEST(DeviceDiscovery, AFaultyGen1UnitIsListedWithItsReasonAndNotChosen) {
  FakeMachine m;
  m.root = test::temp_dir("disc_faulty");
  m.eeproms = {text_of("LKG-2K-04409.visual.json")};
  m.fault = [](test::FakeHoloPlay& d) { d.disconnect_at_page = 3; };
  test::put_calibration(m.root, "/media/me/LKG-P", text_of("LKG-PORT-portrait.visual.json"));
  const Discovery found = discover_devices(m.options());
  ASSERT_EQ(found.devices.size(), 2u);
  EXPECT_FALSE(found.devices[0].readable());
  EXPECT_NE(found.devices[0].problem.find("gone"), std::string::npos) << found.devices[0].problem;
  EXPECT_EQ(select_device(found, "auto").serial, "LKG-PORT-portrait");  // the only readable one
}

TEST(DeviceDiscovery, AnUnreadableUnitAskedForByNameGivesItsReason) {
  FakeMachine m;
  m.root = test::temp_dir("disc_reason");
  fs::create_directories(m.root / "media/me/LKG-P00655/LKG_calibration/visual.json");
  const Discovery found = discover_devices(m.options());
  ASSERT_EQ(found.devices.size(), 1u);
  for (const std::string spec : {"auto", "LKG-P00655"}) {
    try {
      select_device(found, spec);
      FAIL() << spec;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("cannot read"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(select_device(found, "LKG-NOPE"), InputError);
}

TEST(DeviceDiscovery, AUsbUnitWithoutHidrawNodeIsExplained) {
  FakeMachine m;
  m.root = test::temp_dir("disc_usb");
  UsbDeviceSeen seen;
  seen.vendor_id = kGen1VendorId;
  seen.product_id = kGen1ProductId;
  seen.node = "/dev/bus/usb/001/004";
  m.usb.devices = {seen};
  seen.node = "/dev/bus/usb/001/005";
  seen.problem = "permission denied on /dev/bus/usb/001/005: install the udev rules with: ...";
  m.usb.devices.push_back(seen);
  const Discovery found = discover_devices(m.options());
  ASSERT_EQ(found.devices.size(), 2u);
  EXPECT_NE(found.devices[0].problem.find("no hidraw node"), std::string::npos) << found.devices[0].problem;
  EXPECT_NE(found.devices[1].problem.find("permission denied on /dev/bus/usb/001/005"), std::string::npos);
}

TEST(DeviceDiscovery, EachUnitGetsItsMonitorByEdidName) {
  FakeMachine m;
  m.root = test::temp_dir("disc_monitor");
  test::put_calibration(m.root, "/media/me/LKG-P", text_of("LKG-PORT-portrait.visual.json"));
  // card0-DP-1: a Looking Glass Portrait (1536x2048), card0-eDP-1: the laptop panel.
  auto edid = [](const std::string& name, int w, int h) {
    std::string e(128, '\0');
    const uint8_t header[8] = {0, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0};
    for (int i = 0; i < 8; ++i) e[size_t(i)] = char(header[i]);
    e[54] = 1;  // a pixel clock: detailed timing
    e[56] = char(w & 0xff);
    e[58] = char((w >> 8) << 4);
    e[59] = char(h & 0xff);
    e[61] = char((h >> 8) << 4);
    e[66] = char(344 & 0xff);  // image size 344 x 194 mm (a 15.6" panel)
    e[67] = char(194);
    e[68] = char((344 >> 8) << 4);
    e[72 + 3] = char(0xfc);
    std::string text = name + "\n";
    for (size_t i = 0; i < 13; ++i) e[72 + 5 + i] = i < text.size() ? text[i] : ' ';
    return e;
  };
  test::write_file(m.root / "sys/class/drm/card0-DP-1/status", "connected\n");
  test::write_file(m.root / "sys/class/drm/card0-DP-1/edid", edid("LKG-P00655", 1536, 2048));
  test::write_file(m.root / "sys/class/drm/card0-eDP-1/status", "connected\n");
  test::write_file(m.root / "sys/class/drm/card0-eDP-1/edid", edid("Panel", 1920, 1080));
  test::write_file(m.root / "sys/class/drm/card0-HDMI-A-1/status", "disconnected\n");
  const Discovery found = discover_devices(m.options());
  ASSERT_EQ(found.devices.size(), 1u);
  EXPECT_EQ(found.devices[0].monitor, "DP-1 \"LKG-P00655\" 1536x2048") << found.devices[0].monitor_problem;

  const auto monitors = connected_monitors(m.root);
  ASSERT_EQ(monitors.size(), 2u);
  EXPECT_EQ(match_monitor(monitors, "Panel", 1920, 1080).monitor, "eDP-1 \"Panel\" 1920x1080");
  EXPECT_EQ(match_monitor(monitors, "LKG", 2048, 1536).monitor, "DP-1 \"LKG-P00655\" 1536x2048");
  EXPECT_NE(match_monitor(monitors, "LKG", 3840, 2160).problem.find("is 1536x2048, not the display's 3840x2160"),
            std::string::npos);
  EXPECT_NE(match_monitor(monitors, "HDMI", 3840, 2160).problem.find("no monitor"), std::string::npos);
  EXPECT_NE(match_monitor({}, "LKG", 3840, 2160).problem.find("no connected monitor"), std::string::npos);

  // A panel nobody described (`lfd patterns --monitor`): size and DPI from the EDID.
  const MonitorPanel panel = monitor_panel(monitors, "Panel");
  EXPECT_EQ(panel.width_px, 1920);
  EXPECT_EQ(panel.height_px, 1080);
  EXPECT_NEAR(panel.dpi, 1920 / (344 / 25.4), 1e-9);
  EXPECT_NE(panel.monitor.find("344 x 194 mm"), std::string::npos) << panel.monitor;
  EXPECT_THROW(monitor_panel(monitors, ""), InputError);  // two fit
  EXPECT_THROW(monitor_panel(monitors, "HDMI"), InputError);
}

TEST(Edid, ShortOrHeaderlessDataIsNoEdid) {
  EXPECT_FALSE(parse_edid(std::vector<uint8_t>(127, 0)));
  EXPECT_FALSE(parse_edid(std::vector<uint8_t>(128, 0)));
}

}  // namespace
}  // namespace lfd::device
