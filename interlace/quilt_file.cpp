#include "interlace/quilt_file.hpp"

#include "util/error.hpp"

namespace lfd::interlace {

render::QuiltLayout resolve_quilt_layout(const std::filesystem::path& path, int width, int height,
                                         const QuiltOverrides& o, double display_aspect) {
  const std::string name = path.filename().string();
  auto parsed = render::parse_quilt_name(name);
  if (!parsed && (!o.cols || !o.rows))
    throw_input_error("{}: quilt tiling unknown: name the file *_qs{{C}}x{{R}}a{{aspect}}.png or "
                      "give --cols and --rows", path.string());
  render::QuiltLayout q = parsed.value_or(render::QuiltLayout{});
  if (!parsed) q.aspect = display_aspect;
  if (o.cols) q.cols = *o.cols;
  if (o.rows) q.rows = *o.rows;
  q.views = o.views.value_or(q.cols * q.rows);
  if (o.aspect) q.aspect = *o.aspect;
  q.width = width;
  q.height = height;
  q.check(path.string());
  return q;
}

}  // namespace lfd::interlace
