#include "util/atomic_file.hpp"

#include <fstream>
#include <random>
#include <sstream>

#include <fmt/format.h>

#include "util/error.hpp"

namespace lfd {

void write_file_atomic(const std::filesystem::path& path,
                       const std::function<void(const std::filesystem::path&)>& write) {
  namespace fs = std::filesystem;
  if (path.has_parent_path()) fs::create_directories(path.parent_path());
  std::random_device rd;
  const fs::path tmp = path.string() + fmt::format(".tmp{:08x}", rd());
  try {
    write(tmp);
    fs::rename(tmp, path);
  } catch (...) {
    std::error_code ec;
    fs::remove(tmp, ec);
    throw;
  }
}

void write_text_atomic(const std::filesystem::path& path, const std::string& text) {
  write_file_atomic(path, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw std::runtime_error(path.string() + ": cannot write");
  });
}

std::string read_text_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw_input_error("{}: cannot open file", path.string());
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void guard_overwrite(const std::filesystem::path& path, bool force) {
  namespace fs = std::filesystem;
  if (!fs::exists(path)) return;
  if (!force) throw_input_error("{}: already exists (use --force to replace it; a .bak copy is kept)",
                                path.string());
  fs::copy_file(path, path.string() + ".bak", fs::copy_options::overwrite_existing);
}

}  // namespace lfd
