#include "render/quilt_layout.hpp"

#include <cmath>
#include <regex>

#include <fmt/format.h>

#include "util/error.hpp"

namespace lfd::render {

void QuiltLayout::check(const std::string& what) const {
  if (cols <= 0 || rows <= 0) throw_input_error("{}: quilt columns and rows must be positive", what);
  if (views <= 0 || views > cols * rows)
    throw_input_error("{}: {} views do not fit a {}x{} quilt", what, views, cols, rows);
  if (!(aspect > 0) || !std::isfinite(aspect))
    throw_input_error("{}: quilt aspect must be positive and finite", what);
  if (width > 0 && (tile_width() < 1 || tile_height() < 1))
    throw_input_error("{}: a {}x{} image cannot hold {}x{} tiles", what, width, height, cols, rows);
}

std::optional<QuiltLayout> parse_quilt_name(const std::string& filename) {
  static const std::regex re(R"(_qs(\d+)x(\d+)a(\d+(?:\.\d*)?))");
  std::smatch m;
  if (!std::regex_search(filename, m, re)) return std::nullopt;
  QuiltLayout q;
  try {
    q.cols = std::stoi(m[1]);
    q.rows = std::stoi(m[2]);
    q.aspect = std::stod(m[3]);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  q.views = q.cols * q.rows;
  return q;
}

std::string quilt_suffix(int cols, int rows, double aspect) {
  std::string a = fmt::format("{:.4f}", aspect);
  while (!a.empty() && a.back() == '0') a.pop_back();
  if (!a.empty() && a.back() == '.') a.pop_back();
  return fmt::format("_qs{}x{}a{}", cols, rows, a);
}

double snap_to_display_aspect(double aspect, int tile_height, double display_aspect) {
  if (tile_height <= 0 || !(display_aspect > 0)) return aspect;
  return std::abs(aspect - display_aspect) * tile_height <= 1.0 ? display_aspect : aspect;
}

}  // namespace lfd::render
