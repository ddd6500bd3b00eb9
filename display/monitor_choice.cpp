#include "display/monitor_choice.hpp"

#include <fmt/format.h>

#include "util/error.hpp"

namespace lfd::display {

std::string describe_monitors(const std::vector<MonitorInfo>& monitors) {
  if (monitors.empty()) return "none";
  std::string out;
  for (const MonitorInfo& m : monitors)
    out += fmt::format("{}\"{}\" {}x{}", out.empty() ? "" : ", ", m.name, m.width_px,
                       m.height_px);
  return out;
}

size_t choose_monitor(const std::vector<MonitorInfo>& monitors, const std::string& name_prefix,
                      int width_px, int height_px) {
  std::vector<size_t> named;
  for (size_t i = 0; i < monitors.size(); ++i)
    if (!name_prefix.empty() && monitors[i].name.starts_with(name_prefix)) named.push_back(i);
  if (named.size() == 1) return named[0];
  std::vector<size_t> pool = named;
  if (pool.empty())
    for (size_t i = 0; i < monitors.size(); ++i) pool.push_back(i);
  std::vector<size_t> sized;
  for (size_t i : pool)
    if (monitors[i].width_px == width_px && monitors[i].height_px == height_px)
      sized.push_back(i);
  if (sized.size() == 1) return sized[0];
  const std::string named_text =
      named.empty() ? fmt::format("none is named {}...", name_prefix)
                    : fmt::format("{} are named {}...", named.size(), name_prefix);
  if (sized.empty())
    throw_input_error(
        "no monitor for the {}x{} display: {} and {} {}x{}; monitors found: {}; connect the "
        "display or pass --monitor with the start of its name",
        width_px, height_px, named_text, named.empty() ? "none is" : "none of them is",
        width_px, height_px, describe_monitors(monitors));
  throw_input_error(
      "several monitors could be the {}x{} display ({}, {} of them are {}x{}); monitors found: "
      "{}; pass --monitor with the start of its name",
      width_px, height_px, named_text, sized.size(), width_px, height_px,
      describe_monitors(monitors));
}

}  // namespace lfd::display
