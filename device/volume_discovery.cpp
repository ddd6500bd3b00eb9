#include "device/volume_discovery.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "display/visual_json.hpp"
#include "util/error.hpp"

namespace lfd::device {

namespace fs = std::filesystem;

namespace {

// /proc/mounts escapes space, tab, newline and backslash as \ooo octal.
std::string decode_mount_field(const std::string& field) {
  std::string out;
  for (size_t i = 0; i < field.size(); ++i) {
    if (field[i] == '\\' && i + 3 < field.size() &&
        std::all_of(field.begin() + long(i) + 1, field.begin() + long(i) + 4,
                    [](char c) { return c >= '0' && c <= '7'; })) {
      out += char((field[i + 1] - '0') * 64 + (field[i + 2] - '0') * 8 + (field[i + 3] - '0'));
      i += 3;
    } else {
      out += field[i];
    }
  }
  return out;
}

bool pseudo_file_system(const std::string& type) {
  static const std::set<std::string> pseudo = {
      "proc", "sysfs", "devtmpfs", "devpts", "cgroup", "cgroup2", "securityfs", "debugfs",
      "tracefs", "mqueue", "pstore", "bpf", "configfs", "fusectl", "hugetlbfs", "binfmt_misc",
      "autofs", "efivarfs", "rpc_pipefs", "nsfs", "selinuxfs"};
  return pseudo.count(type) > 0;
}

// The folders of `dir` (as seen under root), sorted; none when it cannot be listed.
std::vector<fs::path> subfolders(const fs::path& root, const fs::path& dir) {
  std::vector<fs::path> out;
  std::error_code ec;
  for (fs::directory_iterator it(under_root(root, dir), ec), end; !ec && it != end; it.increment(ec))
    if (it->is_directory(ec)) out.push_back(dir / it->path().filename());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

fs::path under_root(const fs::path& root, const fs::path& path) {
  return (root / path.relative_path()).lexically_normal();
}

bool looks_like_serial(const std::string& name) {
  return name.size() >= 4 && (name[0] == 'L' || name[0] == 'l') && (name[1] == 'K' || name[1] == 'k') &&
         (name[2] == 'G' || name[2] == 'g') &&
         (name[3] == '-' || std::isalnum(static_cast<unsigned char>(name[3])));
}

std::string read_whole_file(const fs::path& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw std::runtime_error("it is a folder, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(std::strerror(errno ? errno : EIO));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw std::runtime_error("read error");
  return text.str();
}

std::vector<fs::path> read_mount_points(const fs::path& root) {
  for (const char* table : {"/proc/self/mounts", "/proc/mounts", "/etc/mtab"}) {
    std::ifstream in(under_root(root, table));
    if (!in) continue;
    std::vector<fs::path> points;
    std::string line;
    while (std::getline(in, line)) {
      std::istringstream fields(line);
      std::string source, point, type;
      if (!(fields >> source >> point >> type) || pseudo_file_system(type)) continue;
      points.emplace_back(decode_mount_field(point));
    }
    return points;
  }
  return {};
}

std::vector<VolumeCalibration> find_volume_calibrations(const fs::path& root, const FileReader& reader) {
  // Candidate volumes: the mount table, then the removable-media folders.
  std::vector<fs::path> candidates;
  for (const fs::path& p : read_mount_points(root))
    if (p.is_absolute()) candidates.push_back(p.lexically_normal());
  for (const fs::path& media : subfolders(root, "/media")) {
    candidates.push_back(media);  // /media/<label>
    for (const fs::path& inner : subfolders(root, media))  // /media/<user>/<label>
      if (inner.filename() != kCalibrationFolder) candidates.push_back(inner);
  }
  for (const fs::path& user : subfolders(root, "/run/media"))
    for (const fs::path& volume : subfolders(root, user)) candidates.push_back(volume);
  for (const fs::path& mnt : subfolders(root, "/mnt")) candidates.push_back(mnt);

  std::set<std::string> seen;
  std::vector<VolumeCalibration> found;
  for (const fs::path& volume : candidates) {
    if (!seen.insert(volume.string()).second) continue;
    VolumeCalibration v;
    v.volume = volume;
    v.file = volume / kCalibrationFolder / kCalibrationFile;
    const fs::path local = under_root(root, v.file);
    std::error_code ec;
    const bool present = fs::exists(local, ec) || fs::exists(under_root(root, volume / kCalibrationFolder), ec);
    const std::string label = volume.filename().string();
    if (!present) {
      if (!looks_like_serial(label)) continue;  // an ordinary volume
      v.serial = label;
      v.problem = fmt::format("the volume {} is named like a Looking Glass but holds no {}/{}",
                              volume.string(), kCalibrationFolder, kCalibrationFile);
      found.push_back(std::move(v));
      continue;
    }
    if (looks_like_serial(label)) v.serial = label;
    try {
      v.text = reader(local);
    } catch (const std::exception& e) {
      v.problem = fmt::format("cannot read {}: {}", v.file.string(), e.what());
      found.push_back(std::move(v));
      continue;
    }
    try {
      const auto display = display::parse_visual_json(v.text, v.file.string());
      display.check(v.file.string());
      if (!display.serial.empty()) v.serial = display.serial;
    } catch (const std::exception& e) {
      v.problem = e.what();
      v.text.clear();
    }
    found.push_back(std::move(v));
  }
  std::sort(found.begin(), found.end(),
            [](const VolumeCalibration& a, const VolumeCalibration& b) { return a.volume < b.volume; });
  return found;
}

}  // namespace lfd::device
