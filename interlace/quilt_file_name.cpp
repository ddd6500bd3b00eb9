#include "interlace/quilt_file_name.hpp"

#include <filesystem>

#include "util/error.hpp"

namespace lfd::interlace {

std::string quilt_file_name(const std::string& path, const render::QuiltLayout& q,
                            const std::string& option) {
  if (const auto named = render::parse_quilt_name(path)) {
    if (named->cols != q.cols || named->rows != q.rows)
      throw_input_error("{}: '{}' names a {}x{} quilt but the quilt is {}x{}", option, path,
                        named->cols, named->rows, q.cols, q.rows);
    return path;
  }
  const std::filesystem::path p(path);
  const std::string name = p.stem().string() + render::quilt_suffix(q.cols, q.rows, q.aspect) +
                           (p.has_extension() ? p.extension().string() : std::string(".png"));
  return (p.parent_path() / name).string();
}

}  // namespace lfd::interlace
