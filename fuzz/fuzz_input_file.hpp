#pragma once
// For the parsers that read only from a path (OpenCV FileStorage for the camera YAML, the
// capture manifest under DIR/patterns/): the fuzz input written to a file in a private temp
// folder, rewritten for every input.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace lfd::fuzz {

// A folder of its own under the temp directory, made once per process and removed at exit
// (left behind only when the process dies on a finding).
inline const std::filesystem::path& scratch_dir() {
  struct Scratch {
    std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("lfd-fuzz-" + std::to_string(::getpid()));
    Scratch() { std::filesystem::create_directories(dir); }
    ~Scratch() {
      std::error_code ignored;
      std::filesystem::remove_all(dir, ignored);
    }
  };
  static const Scratch scratch;
  return scratch.dir;
}

// Writes the input to `relative` under scratch_dir() and returns the path.
inline std::filesystem::path write_input(const std::string& relative, const uint8_t* data,
                                         size_t size) {
  const auto path = scratch_dir() / relative;
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return path;
}

}  // namespace lfd::fuzz
