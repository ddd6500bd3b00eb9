#pragma once
// Directory trees that look like a machine with Looking Glass volumes mounted: a --root for
// volume discovery and for the lfd program.
#include <filesystem>
#include <fstream>
#include <string>

#include "util/atomic_file.hpp"

namespace lfd::test {

inline void write_file(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

// root/<volume>/LKG_calibration/visual.json holding `text`; `volume` is absolute ("/media/me/X").
inline std::filesystem::path put_calibration(const std::filesystem::path& root,
                                             const std::string& volume, const std::string& text) {
  const auto file = root / std::filesystem::path(volume).relative_path() / "LKG_calibration" / "visual.json";
  write_file(file, text);
  return file;
}

}  // namespace lfd::test
