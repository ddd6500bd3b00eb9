// Which monitor the live mode's pattern window opens on: the name prefix first, the display's
// resolution when the name does not decide, an error listing the monitors otherwise.
#include <gtest/gtest.h>

#include "display/monitor_choice.hpp"
#include "util/error.hpp"

namespace lfd::calib {
namespace {

const std::vector<display::MonitorInfo> kDesk = {
    {"DELL U2720Q", 3840, 2160}, {"LKG-P03-AB12", 1536, 2048}, {"eDP-1", 1920, 1080}};

std::string error_of(const std::vector<display::MonitorInfo>& monitors, const std::string& prefix, int w,
                     int h) {
  try {
    display::choose_monitor(monitors, prefix, w, h);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(MonitorChoice, TheOnlyMonitorWithThePrefixWinsWhateverItsResolution) {
  EXPECT_EQ(display::choose_monitor(kDesk, "LKG", 1536, 2048), 1u);
  EXPECT_EQ(display::choose_monitor(kDesk, "LKG", 1440, 2560), 1u);
  EXPECT_EQ(display::choose_monitor(kDesk, "eDP", 1536, 2048), 2u);
}

TEST(MonitorChoice, WithoutANameMatchTheDisplaysResolutionDecides) {
  EXPECT_EQ(display::choose_monitor(kDesk, "XYZ", 1920, 1080), 2u);
  EXPECT_EQ(display::choose_monitor(kDesk, "", 3840, 2160), 0u);
}

TEST(MonitorChoice, SeveralNameMatchesAreSettledByResolution) {
  const std::vector<display::MonitorInfo> two = {{"LKG-2K", 2560, 1600}, {"LKG-P", 1536, 2048}};
  EXPECT_EQ(display::choose_monitor(two, "LKG", 1536, 2048), 1u);
  EXPECT_NE(error_of(two, "LKG", 1920, 1080).find("2 are named LKG"), std::string::npos);
}

TEST(MonitorChoice, NoMatchIsAnInputErrorListingEveryMonitor) {
  const std::string e = error_of(kDesk, "LKG-X", 2560, 1600);
  EXPECT_NE(e.find("2560x1600"), std::string::npos) << e;
  for (const display::MonitorInfo& m : kDesk) {
    EXPECT_NE(e.find("\"" + m.name + "\""), std::string::npos) << e;
    EXPECT_NE(e.find(std::to_string(m.width_px) + "x" + std::to_string(m.height_px)),
              std::string::npos)
        << e;
  }
}

TEST(MonitorChoice, TwoMonitorsOfTheDisplaysResolutionAreAmbiguous) {
  const std::vector<display::MonitorInfo> twins = {{"HDMI-1", 1920, 1080}, {"eDP-1", 1920, 1080}};
  EXPECT_NE(error_of(twins, "LKG", 1920, 1080).find("--monitor"), std::string::npos);
}

TEST(MonitorChoice, NoMonitorsAtAllSaysNone) {
  EXPECT_NE(error_of({}, "LKG", 1536, 2048).find("monitors found: none"), std::string::npos);
}

}  // namespace
}  // namespace lfd::calib
