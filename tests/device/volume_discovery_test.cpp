// Finding LKG_calibration/visual.json on mounted volumes, on trees built under a --root: the
// mount table (with escaped names), /media, /media/<user>, /run/media/<user>, /mnt; two units at
// once; volumes named after a serial without a calibration; unreadable and invalid files.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "device/volume_discovery.hpp"
#include "tests/device/device_test_tree.hpp"
#include "tests/test_data.hpp"
#include "util/atomic_file.hpp"

namespace lfd::device {
namespace {

namespace fs = std::filesystem;

std::string portrait() { return read_text_file(test::fixture_calibration("LKG-PORT-portrait.visual.json")); }
std::string gen2() { return read_text_file(test::fixture_calibration("LKG-APW92011.visual.json")); }

TEST(VolumeDiscovery, EmptyRootFindsNothing) {
  const fs::path root = test::temp_dir("vol_empty");
  EXPECT_TRUE(find_volume_calibrations(root).empty());
  EXPECT_TRUE(read_mount_points(root).empty());
}

TEST(VolumeDiscovery, FindsAVolumeInTheMountTableWithItsBytesAndSerial) {
  const fs::path root = test::temp_dir("vol_mounts");
  test::write_file(root / "proc/self/mounts",
                   "proc /proc proc rw 0 0\n"
                   "/dev/sda1 / ext4 rw 0 0\n"
                   "/dev/sdb1 /srv/my\\040display vfat ro 0 0\n");
  test::put_calibration(root, "/srv/my display", gen2());
  const auto found = find_volume_calibrations(root);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].volume, fs::path("/srv/my display"));
  EXPECT_EQ(found[0].file, fs::path("/srv/my display/LKG_calibration/visual.json"));
  EXPECT_EQ(found[0].text, gen2());
  EXPECT_EQ(found[0].serial, "LKG-APW92011");
  EXPECT_TRUE(found[0].problem.empty()) << found[0].problem;
}

TEST(VolumeDiscovery, MountTableSkipsPseudoFileSystemsAndDecodesEscapes) {
  const fs::path root = test::temp_dir("vol_table");
  test::write_file(root / "proc/mounts", "sysfs /sys sysfs rw 0 0\n/dev/sdc1 /a\\011b\\134c vfat rw 0 0\n");
  const auto points = read_mount_points(root);
  ASSERT_EQ(points.size(), 1u);
  EXPECT_EQ(points[0], fs::path("/a\tb\\c"));
}

TEST(VolumeDiscovery, FindsTwoUnitsUnderMediaAndRunMedia) {
  const fs::path root = test::temp_dir("vol_two");
  test::put_calibration(root, "/media/me/LKG-PORT", portrait());
  test::put_calibration(root, "/run/media/you/LKG-A0001", gen2());
  test::write_file(root / "media/me/USBSTICK/notes.txt", "not a display");
  const auto found = find_volume_calibrations(root);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].volume, fs::path("/media/me/LKG-PORT"));
  EXPECT_EQ(found[0].text, portrait());
  EXPECT_EQ(found[1].volume, fs::path("/run/media/you/LKG-A0001"));
  EXPECT_EQ(found[1].serial, "LKG-APW92011");  // the file's serial, not the volume's name
}

TEST(VolumeDiscovery, AVolumeInTheTableAndUnderMediaIsFoundOnce) {
  const fs::path root = test::temp_dir("vol_once");
  test::write_file(root / "proc/self/mounts", "/dev/sdb1 /media/me/LKG-P00655 vfat ro 0 0\n");
  test::put_calibration(root, "/media/me/LKG-P00655", portrait());
  EXPECT_EQ(find_volume_calibrations(root).size(), 1u);
}

TEST(VolumeDiscovery, FindsAVolumeDirectlyUnderMediaAndMnt) {
  const fs::path root = test::temp_dir("vol_mnt");
  test::put_calibration(root, "/media/LKG-P1", portrait());
  test::put_calibration(root, "/mnt/usb", gen2());
  EXPECT_EQ(find_volume_calibrations(root).size(), 2u);
}

TEST(VolumeDiscovery, AVolumeNamedAfterASerialWithoutCalibrationIsReportedWithTheReason) {
  const fs::path root = test::temp_dir("vol_named");
  fs::create_directories(root / "media/me/LKG-P00655");
  const auto found = find_volume_calibrations(root);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].serial, "LKG-P00655");
  EXPECT_NE(found[0].problem.find("holds no LKG_calibration/visual.json"), std::string::npos)
      << found[0].problem;
}

TEST(VolumeDiscovery, AnUnreadableFileIsReportedNotSkipped) {
  // Running as root, permissions do not stop a read: a folder where the file should be does.
  const fs::path root = test::temp_dir("vol_unreadable");
  fs::create_directories(root / "media/me/LKG-P00655/LKG_calibration/visual.json");
  test::put_calibration(root, "/media/me/LKG-A0001", gen2());
  const auto found = find_volume_calibrations(root);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_TRUE(found[0].problem.empty());
  EXPECT_EQ(found[1].serial, "LKG-P00655");
  EXPECT_NE(found[1].problem.find("cannot read /media/me/LKG-P00655/LKG_calibration/visual.json"),
            std::string::npos) << found[1].problem;
  EXPECT_TRUE(found[1].text.empty());
}

TEST(VolumeDiscovery, AReaderThatFailsGivesItsReason) {
  const fs::path root = test::temp_dir("vol_reader");
  test::put_calibration(root, "/media/me/LKG-P00655", portrait());
  const auto found = find_volume_calibrations(root, [](const fs::path&) -> std::string {
    throw std::runtime_error("Permission denied");
  });
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NE(found[0].problem.find("Permission denied"), std::string::npos);
}

TEST(VolumeDiscovery, AnInvalidCalibrationIsReportedWithTheParsersReason) {
  const fs::path root = test::temp_dir("vol_invalid");
  test::put_calibration(root, "/media/me/LKG-P00655", "{\"pitch\": {\"value\": ");
  const auto found = find_volume_calibrations(root);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NE(found[0].problem.find("/media/me/LKG-P00655/LKG_calibration/visual.json"),
            std::string::npos) << found[0].problem;
  EXPECT_TRUE(found[0].text.empty());
}

TEST(VolumeDiscovery, SerialNamesAreRecognised) {
  EXPECT_TRUE(looks_like_serial("LKG-P00655"));
  EXPECT_TRUE(looks_like_serial("lkg-2k-04409"));
  EXPECT_TRUE(looks_like_serial("LKG01Do12HjQE"));
  EXPECT_FALSE(looks_like_serial("USBSTICK"));
  EXPECT_FALSE(looks_like_serial("LKG"));
  EXPECT_FALSE(looks_like_serial("LKG_calibration"));
}

}  // namespace
}  // namespace lfd::device
