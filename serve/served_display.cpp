// Served displays from calibration files (docs/serve.md, "Calibration").
#include "serve/served_display.hpp"

#include "display/display_quilt.hpp"
#include "display/visual_json.hpp"
#include "util/atomic_file.hpp"

namespace lfd::serve {

ServedDisplay served_display_from(int index, const display::Calibration& calibration,
                                  const std::filesystem::path& file, bool lfd_calibration) {
  ServedDisplay d;
  d.index = index;
  d.calibration = calibration;
  d.calibration_path = file;
  d.calibration_source = lfd_calibration ? "lfd calibration.json" : "factory visual.json";
  const std::string& serial = calibration.display.serial;
  d.hwid = serial.rfind("LKG", 0) == 0 ? serial : "LKG-lfd-" + (serial.empty() ? std::to_string(index) : serial);
  d.hardware_version = "lfd";
  const display::DisplayQuilt quilt = display::quilt_for_display(calibration);
  const display::ViewSize view = display::view_size_for_display(quilt);
  d.default_quilt = {quilt.grid.cols, quilt.grid.rows, quilt.views, quilt.view_aspect};
  d.quilt_width_px = view.width * quilt.grid.cols;
  d.quilt_height_px = view.height * quilt.grid.rows;
  return d;
}

ServedDisplay served_display_from_file(int index, const std::filesystem::path& file) {
  const display::Calibration calibration = display::read_calibration(file);
  const auto root = display::parse_json_object(read_text_file(file), file.string());
  const bool lfd = root.contains("format") && root["format"] == "lfd-calibration";
  return served_display_from(index, calibration, file, lfd);
}

}  // namespace lfd::serve

namespace lfd::serve {

std::vector<ServedDisplay> served_displays(const std::vector<std::filesystem::path>& files,
                                           const std::vector<display::Calibration>& devices) {
  std::vector<ServedDisplay> from_files;
  for (const auto& f : files) from_files.push_back(served_display_from_file(0, f));
  std::vector<bool> used(from_files.size(), false);
  std::vector<ServedDisplay> out;
  for (const display::Calibration& device : devices) {
    bool replaced = false;
    for (std::size_t i = 0; i < from_files.size() && !replaced; ++i) {
      if (used[i] || device.display.serial.empty() ||
          from_files[i].calibration.display.serial != device.display.serial)
        continue;
      used[i] = replaced = true;
      out.push_back(from_files[i]);
    }
    if (!replaced) out.push_back(served_display_from(0, device, "device " + device.display.serial, false));
  }
  for (std::size_t i = 0; i < from_files.size(); ++i)
    if (!used[i]) out.push_back(from_files[i]);
  for (std::size_t i = 0; i < out.size(); ++i) out[i].index = static_cast<int>(i);
  return out;
}

}  // namespace lfd::serve
