#pragma once
// Simulated captures kept on disk between the test processes of one build. CTest runs every test
// in a process of its own (gtest_discover_tests), so a suite's static fixture is simulated once
// per test: the bad-input suite's one Portrait position took ~15 s in each of its 15 tests. The
// first process to ask simulates and writes the Mats' bytes as they are (exact: the tests see the
// same pixels either way); the others read them. The key is the caller's name for the settings
// and this test program's own file (size and modification time), so a rebuilt program, whose
// simulator may have changed, simulates afresh. Written atomically: two processes that miss at
// once both simulate, and either file is the same. An earlier build's file of the same name is
// removed when this build writes its own.
#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "sim/capture_io.hpp"

namespace lfd::test {

namespace cached_captures_detail {

inline std::string program_stamp() {
  struct stat st {};
  if (::stat("/proc/self/exe", &st) != 0) return "";
  return std::to_string(st.st_size) + "-" + std::to_string(st.st_mtim.tv_sec) + "-" +
         std::to_string(st.st_mtim.tv_nsec);
}

inline void write_string(std::ostream& out, const std::string& s) {
  const uint64_t n = s.size();
  out.write(reinterpret_cast<const char*>(&n), sizeof n);
  out.write(s.data(), std::streamsize(n));
}

inline bool read_string(std::istream& in, std::string& s) {
  uint64_t n = 0;
  if (!in.read(reinterpret_cast<char*>(&n), sizeof n) || n > (uint64_t(1) << 30)) return false;
  s.resize(n);
  return bool(in.read(s.data(), std::streamsize(n)));
}

inline void write_captures(const std::filesystem::path& path, const std::vector<sim::PositionCaptures>& captures) {
  const std::filesystem::path tmp = path.string() + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary);
    const uint64_t positions = captures.size();
    out.write(reinterpret_cast<const char*>(&positions), sizeof positions);
    for (const sim::PositionCaptures& pc : captures) {
      write_string(out, pc.name);
      const uint64_t images = pc.images.size();
      out.write(reinterpret_cast<const char*>(&images), sizeof images);
      for (const auto& [stem, image] : pc.images) {
        const cv::Mat m = image.isContinuous() ? image : image.clone();
        const int32_t header[3] = {m.type(), m.rows, m.cols};
        write_string(out, stem);
        out.write(reinterpret_cast<const char*>(header), sizeof header);
        out.write(reinterpret_cast<const char*>(m.data), std::streamsize(m.total() * m.elemSize()));
      }
      const uint64_t paths = pc.paths.size();
      out.write(reinterpret_cast<const char*>(&paths), sizeof paths);
      for (const auto& [stem, file] : pc.paths) {
        write_string(out, stem);
        write_string(out, file);
      }
    }
    if (!out) return;  // a full disk: the next process simulates again
  }
  // Another process of this build may have written the same file first (and a stale-file sweep
  // of a concurrent writer may have taken this tmp): either way the cache holds it or not.
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) std::filesystem::remove(tmp, ec);
}

inline bool read_captures(const std::filesystem::path& path, std::vector<sim::PositionCaptures>& captures) {
  std::ifstream in(path, std::ios::binary);
  uint64_t positions = 0;
  if (!in.read(reinterpret_cast<char*>(&positions), sizeof positions) || positions > 64) return false;
  captures.resize(positions);
  for (sim::PositionCaptures& pc : captures) {
    uint64_t images = 0;
    if (!read_string(in, pc.name) || !in.read(reinterpret_cast<char*>(&images), sizeof images) || images > 256)
      return false;
    for (uint64_t i = 0; i < images; ++i) {
      std::string stem;
      int32_t header[3] = {};
      if (!read_string(in, stem) || !in.read(reinterpret_cast<char*>(header), sizeof header)) return false;
      cv::Mat m(header[1], header[2], header[0]);
      if (!in.read(reinterpret_cast<char*>(m.data), std::streamsize(m.total() * m.elemSize()))) return false;
      pc.images.emplace(stem, m);
    }
    uint64_t paths = 0;
    if (!in.read(reinterpret_cast<char*>(&paths), sizeof paths) || paths > 256) return false;
    for (uint64_t i = 0; i < paths; ++i) {
      std::string stem, file;
      if (!read_string(in, stem) || !read_string(in, file)) return false;
      pc.paths.emplace(stem, file);
    }
  }
  return true;
}

}  // namespace cached_captures_detail

// The captures `simulate` makes, from the build's test cache when this program already made them.
inline std::vector<sim::PositionCaptures> cached_captures(
    const std::string& name, const std::function<std::vector<sim::PositionCaptures>()>& simulate) {
  namespace d = cached_captures_detail;
  const std::string stamp = d::program_stamp();
  const std::filesystem::path dir = std::filesystem::path(LFD_BINARY_DIR) / "test-cache";
  const std::filesystem::path path = dir / (name + "-" + stamp + ".captures");
  std::vector<sim::PositionCaptures> captures;
  if (!stamp.empty() && d::read_captures(path, captures)) return captures;
  captures = simulate();
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (stamp.empty() || ec) return captures;
  // An earlier build's copies of these captures are stale now: only this program's stay.
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const std::string file = entry.path().filename().string();
    // Only finished files of other builds: a .tmp is a concurrent writer's, still being written.
    if (file.rfind(name + "-", 0) == 0 && entry.path() != path && file.find(".tmp") == std::string::npos)
      std::filesystem::remove(entry.path(), ec);
  }
  d::write_captures(path, captures);
  return captures;
}

}  // namespace lfd::test
