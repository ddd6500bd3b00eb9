#include "media/quilt_name.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>

#include "util/error.hpp"

namespace lfd::media {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Digits at `pos` as an int no larger than `max` (advances pos); nullopt otherwise.
std::optional<int> read_count(std::string_view s, size_t& pos, int max) {
  const size_t start = pos;
  while (pos < s.size() && is_digit(s[pos]) && pos - start < 6) ++pos;
  if (pos == start || (pos < s.size() && is_digit(s[pos]))) return std::nullopt;
  int value = 0;
  std::from_chars(s.data() + start, s.data() + pos, value);
  if (value < 1 || value > max) return std::nullopt;
  return value;
}

// `\d+(\.\d*)?` at `pos`, bounded to a dozen characters.
std::optional<double> read_aspect(std::string_view s, size_t& pos) {
  const size_t start = pos;
  while (pos < s.size() && is_digit(s[pos])) ++pos;
  if (pos == start) return std::nullopt;
  if (pos < s.size() && s[pos] == '.') {
    ++pos;
    while (pos < s.size() && is_digit(s[pos])) ++pos;
  }
  if (pos - start > 12) return std::nullopt;
  double value = 0;
  const auto [end, ec] = std::from_chars(s.data() + start, s.data() + pos, value);
  if (ec != std::errc() || !(value >= kMinQuiltAspect && value <= kMaxQuiltAspect)) return std::nullopt;
  return value;
}

std::optional<QuiltName> parse_at(std::string_view s, size_t pos) {
  QuiltName q;
  const auto cols = read_count(s, pos, kMaxQuiltTilesPerAxis);
  if (!cols || pos >= s.size() || s[pos] != 'x') return std::nullopt;
  ++pos;
  const auto rows = read_count(s, pos, kMaxQuiltTilesPerAxis);
  if (!rows || pos >= s.size() || s[pos] != 'a') return std::nullopt;
  ++pos;
  const auto aspect = read_aspect(s, pos);
  if (!aspect) return std::nullopt;
  return QuiltName{*cols, *rows, *aspect};
}

}  // namespace

std::optional<QuiltName> parse_quilt_name(std::string_view filename) {
  for (size_t at = filename.find("_qs"); at != std::string_view::npos; at = filename.find("_qs", at + 1))
    if (auto q = parse_at(filename, at + 3)) return q;
  return std::nullopt;
}

render::QuiltLayout quilt_layout_for(const std::string& name, int width, int height,
                                     const interlace::QuiltOverrides& o, double display_aspect) {
  const auto named = parse_quilt_name(std::filesystem::path(name).filename().string());
  if (!named && (!o.cols || !o.rows))
    throw_input_error("{}: quilt tiling unknown: name the file *_qs{{C}}x{{R}}a{{aspect}}.ext or give "
                      "the columns and rows", name);
  render::QuiltLayout q;
  q.cols = o.cols.value_or(named ? named->cols : 0);
  q.rows = o.rows.value_or(named ? named->rows : 0);
  q.aspect = o.aspect.value_or(named ? named->aspect : display_aspect);
  q.width = width;
  q.height = height;
  if (q.cols < 1 || q.rows < 1 || q.cols > kMaxQuiltTilesPerAxis || q.rows > kMaxQuiltTilesPerAxis)
    throw_input_error("{}: quilt columns and rows must be 1 to {}", name, kMaxQuiltTilesPerAxis);
  q.views = o.views.value_or(q.cols * q.rows);
  q.check(name);  // views fit, aspect positive, tiles at least a pixel
  const double tile_aspect = double(q.tile_width()) / q.tile_height();
  const double mismatch = std::max(tile_aspect / q.aspect, q.aspect / tile_aspect);
  if (q.tile_width() < kMinQuiltTilePx || q.tile_height() < kMinQuiltTilePx || !(mismatch <= kMaxTileAspectMismatch))
    throw_input_error("{}: the quilt {} {}x{} tiles at aspect {} but the {}x{} picture gives {}x{} px "
                      "tiles (aspect {:.3g}): not a quilt of that grid",
                      name, named && !o.cols ? "name says" : "tiling is", q.cols, q.rows, q.aspect, width,
                      height, q.tile_width(), q.tile_height(), tile_aspect);
  return q;
}

}  // namespace lfd::media
