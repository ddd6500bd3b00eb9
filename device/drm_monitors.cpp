#include "device/drm_monitors.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>

#include <fmt/format.h>

#include "device/volume_discovery.hpp"
#include "util/error.hpp"

namespace lfd::device {

namespace fs = std::filesystem;

std::optional<EdidSummary> parse_edid(std::span<const uint8_t> edid) {
  static constexpr uint8_t kHeader[8] = {0x00, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0x00};
  if (edid.size() < 128 || !std::equal(kHeader, kHeader + 8, edid.begin())) return std::nullopt;
  EdidSummary summary;
  // Four 18-byte descriptors at 54: a detailed timing has a nonzero pixel clock; a display
  // descriptor starts 00 00 00 <tag>, tag 0xFC holding up to 13 characters of the name.
  for (size_t offset = 54; offset + 18 <= 126; offset += 18) {
    const uint8_t* d = edid.data() + offset;
    if (d[0] != 0 || d[1] != 0) {
      if (summary.width_px == 0) {
        summary.width_px = d[2] | ((d[4] & 0xf0) << 4);
        summary.height_px = d[5] | ((d[7] & 0xf0) << 4);
        summary.width_mm = d[12] | ((d[14] & 0xf0) << 4);
        summary.height_mm = d[13] | ((d[14] & 0x0f) << 8);
      }
    } else if (d[3] == 0xfc) {
      std::string name;
      for (int i = 5; i < 18 && d[i] != '\n' && d[i] != 0; ++i) name += char(d[i]);
      while (!name.empty() && name.back() == ' ') name.pop_back();
      summary.name = name;
    }
  }
  if (summary.width_mm == 0 || summary.height_mm == 0) {  // the basic block's centimetres
    summary.width_mm = 10 * edid[21];
    summary.height_mm = 10 * edid[22];
  }
  return summary;
}

std::vector<ConnectedMonitor> connected_monitors(const fs::path& root) {
  std::vector<ConnectedMonitor> found;
  std::error_code ec;
  for (fs::directory_iterator it(under_root(root, "/sys/class/drm"), ec), end; !ec && it != end;
       it.increment(ec)) {
    const std::string entry = it->path().filename().string();  // card0-DP-1
    const size_t dash = entry.find('-');
    if (!entry.starts_with("card") || dash == std::string::npos) continue;
    std::ifstream status(it->path() / "status");
    std::string state;
    if (!(status >> state) || state != "connected") continue;
    std::ifstream in(it->path() / "edid", std::ios::binary);
    const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto edid = parse_edid(bytes);
    if (!edid) continue;
    found.push_back({entry.substr(dash + 1), {edid->name, edid->width_px, edid->height_px},
                     edid->width_mm, edid->height_mm});
  }
  std::sort(found.begin(), found.end(),
            [](const ConnectedMonitor& a, const ConnectedMonitor& b) { return a.connector < b.connector; });
  return found;
}

MonitorMatch match_monitor(const std::vector<ConnectedMonitor>& monitors,
                           const std::string& name_prefix, int width_px, int height_px) {
  MonitorMatch match;
  if (monitors.empty()) {
    match.problem = "no connected monitor found (no DRM connectors with an EDID)";
    return match;
  }
  std::vector<display::MonitorInfo> infos;
  for (const ConnectedMonitor& m : monitors) infos.push_back(m.monitor);
  try {
    const size_t i = display::choose_monitor(infos, name_prefix, width_px, height_px);
    const ConnectedMonitor& m = monitors[i];
    // The rule trusts a lone LKG name; a unit whose panel differs is another unit's monitor
    // (a portrait panel may report its mode turned: either orientation counts).
    const int w = m.monitor.width_px, h = m.monitor.height_px;
    if (!((w == width_px && h == height_px) || (w == height_px && h == width_px))) {
      match.problem = fmt::format("the monitor {} \"{}\" is {}x{}, not the display's {}x{}",
                                  m.connector, m.monitor.name, w, h, width_px, height_px);
      return match;
    }
    match.monitor = fmt::format("{} \"{}\" {}x{}", m.connector, m.monitor.name, m.monitor.width_px,
                                m.monitor.height_px);
  } catch (const InputError& e) {
    match.problem = e.what();
  }
  return match;
}

MonitorPanel monitor_panel(const std::vector<ConnectedMonitor>& monitors,
                           const std::string& name_prefix) {
  std::vector<const ConnectedMonitor*> fit;
  std::string all;
  for (const ConnectedMonitor& m : monitors) {
    all += fmt::format("{}{} \"{}\" {}x{}", all.empty() ? "" : ", ", m.connector, m.monitor.name,
                       m.monitor.width_px, m.monitor.height_px);
    if (m.monitor.name.starts_with(name_prefix)) fit.push_back(&m);
  }
  if (fit.size() != 1)
    throw_input_error("--monitor {}: {} connected monitors fit ({}); name one by the start of "
                      "its name, or give --screen WxH --dpi D",
                      name_prefix.empty() ? "\"\"" : name_prefix, fit.size(),
                      all.empty() ? "none connected" : all);
  const ConnectedMonitor& m = *fit.front();
  if (m.width_mm <= 0 || m.height_mm <= 0 || m.monitor.width_px <= 0)
    throw_input_error("--monitor {}: {} \"{}\" does not say its physical size in its EDID; give "
                      "--screen WxH --dpi D",
                      name_prefix, m.connector, m.monitor.name);
  MonitorPanel p;
  p.width_px = m.monitor.width_px;
  p.height_px = m.monitor.height_px;
  p.dpi = m.monitor.width_px / (m.width_mm / 25.4);
  p.monitor = fmt::format("{} \"{}\" {}x{}, {} x {} mm", m.connector, m.monitor.name,
                          p.width_px, p.height_px, m.width_mm, m.height_mm);
  return p;
}

}  // namespace lfd::device
