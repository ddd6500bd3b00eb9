#pragma once
// Looking Glass units after Gen1 carry their calibration as LKG_calibration/visual.json on a USB
// mass-storage volume (docs/devices.md "Sources"). The volumes are found in
// the mount table (/proc/self/mounts, else /proc/mounts), and in the folders desktops mount
// removable media under (/media/*, /media/<user>/*, /run/media/<user>/*, /mnt/*). A volume named
// after a serial ("LKG-...") without a readable calibration is reported too, with the reason.
//
// Every path is searched under `root` ("/" normally; a container's or chroot's root, or a tree
// a test builds); results name paths as the system under `root` sees them.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace lfd::device {

// Reads a whole file; throws (any std::exception, its what() becomes the reason) when it cannot.
using FileReader = std::function<std::string(const std::filesystem::path&)>;
std::string read_whole_file(const std::filesystem::path& path);  // the default FileReader

struct VolumeCalibration {
  std::filesystem::path volume;  // the mount point, as seen under root (/media/me/LKG-P00655)
  std::filesystem::path file;    // volume / LKG_calibration/visual.json, as seen under root
  std::string serial;            // from visual.json; else the volume's name when it is a serial
  std::string text;              // visual.json as the volume holds it; empty with a problem
  std::string problem;           // why it cannot be used; empty when it can
};

inline constexpr const char* kCalibrationFolder = "LKG_calibration";
inline constexpr const char* kCalibrationFile = "visual.json";

// The mount points of the table at `root`/proc/self/mounts (or /proc/mounts), decoded (\040 is a
// space), without kernel pseudo file systems. Empty when no table can be read.
std::vector<std::filesystem::path> read_mount_points(const std::filesystem::path& root);

// Every calibration volume under `root`, sorted by volume path, each volume once.
std::vector<VolumeCalibration> find_volume_calibrations(const std::filesystem::path& root,
                                                        const FileReader& reader = read_whole_file);

// `path` (absolute, as seen under root) made a path on this machine: root / path.
std::filesystem::path under_root(const std::filesystem::path& root, const std::filesystem::path& path);

// True for serials of Looking Glass units ("LKG-..." and "LKG..." EDID-style names, any case).
bool looks_like_serial(const std::string& name);

}  // namespace lfd::device
