#pragma once
// The udev rules lfd ships (data/udev/60-lookingglass.rules) give the person at the seat access
// to the Gen1 HID node and the USB device node; a permission error says how to get them.
#include <filesystem>
#include <string>

namespace lfd::device {

inline constexpr const char* kUdevRulesName = "60-lookingglass.rules";

// The rules file that ships with this program: in the source tree's data/udev, or where
// `cmake --install` put it (<prefix>/lib/udev/rules.d). Empty when neither exists.
std::filesystem::path bundled_udev_rules();

// One sentence: when the rules are installed where udev reads them, to replug the display;
// otherwise the one command that installs them.
std::string udev_rules_advice();

}  // namespace lfd::device
