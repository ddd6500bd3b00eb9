#include "device/udev_rules.hpp"

#include <fmt/format.h>

#include "util/data_dir.hpp"

namespace lfd::device {

namespace fs = std::filesystem;

fs::path bundled_udev_rules() {
  const fs::path data = data_dir();
  for (const fs::path& candidate :
       {data / "udev" / kUdevRulesName,
        data.parent_path().parent_path() / "lib" / "udev" / "rules.d" / kUdevRulesName}) {
    std::error_code ec;
    if (fs::is_regular_file(candidate, ec)) return candidate.lexically_normal();
  }
  return {};
}

std::string udev_rules_advice() {
  for (const char* dir : {"/etc/udev/rules.d", "/lib/udev/rules.d", "/usr/lib/udev/rules.d"}) {
    std::error_code ec;
    const fs::path installed = fs::path(dir) / kUdevRulesName;
    if (fs::is_regular_file(installed, ec))
      return fmt::format("the udev rules are installed ({}) but were not applied to this node: "
                         "unplug and replug the display, or run: sudo udevadm trigger",
                         installed.string());
  }
  const fs::path rules = bundled_udev_rules();
  const std::string source =
      rules.empty() ? std::string("data/udev/") + kUdevRulesName : rules.string();
  return fmt::format("install the udev rules with: sudo install -m 644 {} /etc/udev/rules.d/ && "
                     "sudo udevadm control --reload-rules && sudo udevadm trigger",
                     source);
}

}  // namespace lfd::device
