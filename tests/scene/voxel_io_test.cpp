// The voxel files: .voxels round trip and its checks, the svraster-webgl PLY (layout of f_rest
// and grid values, positions from the centre), and the split from Gaussian PLYs.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "scene/gaussian_io.hpp"
#include "util/error.hpp"
#include "scene/voxel_io.hpp"

namespace lfd::scene {
namespace {

namespace fs = std::filesystem;

scene::VoxelScene two_voxels() {
  scene::VoxelScene s;
  s.scene_center = {0.5f, -1.0f, 2.0f};
  s.scene_extent = 4.0f;
  s.sh_degree = 1;
  s.supersampling = 1.5f;
  s.samples_per_voxel = 2;
  s.background = {0.1f, 0.2f, 0.3f};
  s.resize(2);
  s.octree_index = {{1, 0, 3}, {0, 1, 0}};
  s.level = {2, 1};
  for (size_t i = 0; i < 2; ++i)
    for (int k = 0; k < 8; ++k) s.corner_density[i][size_t(k)] = float(k) - float(i) * 3.0f;
  for (size_t k = 0; k < s.sh.size(); ++k) s.sh[k] = 0.01f * float(k);
  return s;
}

void expect_same(const scene::VoxelScene& a, const scene::VoxelScene& b) {
  EXPECT_EQ(a.scene_center, b.scene_center);
  EXPECT_EQ(a.scene_extent, b.scene_extent);
  EXPECT_EQ(a.sh_degree, b.sh_degree);
  EXPECT_EQ(a.octree_index, b.octree_index);
  EXPECT_EQ(a.level, b.level);
  EXPECT_EQ(a.corner_density, b.corner_density);
  EXPECT_EQ(a.sh, b.sh);
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(VoxelFile, RoundTripsEveryField) {
  const scene::VoxelScene s = two_voxels();
  const scene::VoxelScene back = scene::read_voxel_file(scene::encode_voxel_file(s), "t.voxels");
  expect_same(s, back);
  EXPECT_EQ(back.supersampling, 1.5f);
  EXPECT_EQ(back.samples_per_voxel, 2);
  EXPECT_EQ(back.background, s.background);
}

TEST(VoxelFile, TruncatedOrBadFilesNameTheField) {
  const std::string bytes = scene::encode_voxel_file(two_voxels());
  EXPECT_NE(error_of([&] { scene::read_voxel_file(bytes.substr(0, bytes.size() - 1), "t.voxels"); }).find("t.voxels: count"),
            std::string::npos);
  EXPECT_NE(error_of([&] { scene::read_voxel_file(bytes.substr(0, 20), "t.voxels"); }).find("header"), std::string::npos);
  std::string bad_level = bytes;
  bad_level[60 + 12] = 17;  // first voxel's level (header is 60 bytes)
  EXPECT_NE(error_of([&] { scene::read_voxel_file(bad_level, "t.voxels"); }).find("voxel 0: level 17"), std::string::npos);
  std::string outside = bytes;
  outside[60] = 4;  // x index 4 on a level-2 grid of 4
  EXPECT_NE(error_of([&] { scene::read_voxel_file(outside, "t.voxels"); }).find("outside the level-2 grid"), std::string::npos);
}

// An svraster-webgl style ASCII PLY of `s` (SH degree 1): centres, octlevel, a 32-bit octpath,
// f_dc, f_rest coefficient-major RGB innermost, grid0..7_value.
std::string webgl_ply(const scene::VoxelScene& s, bool with_comments = true) {
  std::string out = "ply\nformat ascii 1.0\n";
  if (with_comments)
    out += fmt::format("comment scene_center {} {} {}\ncomment scene_extent {}\n", s.scene_center.x,
                       s.scene_center.y, s.scene_center.z, s.scene_extent);
  out += fmt::format("element vertex {}\nproperty float x\nproperty float y\nproperty float z\n", s.size());
  out += "property uchar octlevel\nproperty uint octpath\n";
  for (int c = 0; c < 3; ++c) out += fmt::format("property float f_dc_{}\n", c);
  for (int k = 0; k < 9; ++k) out += fmt::format("property float f_rest_{}\n", k);
  for (int k = 0; k < 8; ++k) out += fmt::format("property float grid{}_value\n", k);
  out += "end_header\n";
  for (size_t i = 0; i < s.size(); ++i) {
    const glm::vec3 c = s.voxel_center(i);
    out += fmt::format("{} {} {} {} 0", c.x, c.y, c.z, int(s.level[i]));
    for (int k = 0; k < 12; ++k) out += fmt::format(" {}", s.voxel_sh(i)[k]);
    for (float d : s.corner_density[i]) out += fmt::format(" {}", d);
    out += "\n";
  }
  return out;
}

TEST(VoxelPly, ReadsTheSvrasterWebglLayoutWithPositionsFromTheCentres) {
  const scene::VoxelScene s = two_voxels();
  const scene::VoxelScene back = scene::read_voxel_scene_bytes(webgl_ply(s), "s.ply");
  expect_same(s, back);
}

TEST(VoxelPly, WithoutTheSceneCommentsItSaysWhichIsMissing) {
  EXPECT_NE(error_of([&] { scene::read_voxel_ply(webgl_ply(two_voxels(), false), "s.ply"); })
                .find("s.ply: comment scene_center: missing"),
            std::string::npos);
}

TEST(VoxelPly, TheGaussianLoaderPointsToTheVoxelPath) {
  const fs::path path = fs::temp_directory_path() / "lfd_voxel_io_test_webgl.ply";
  std::ofstream(path) << webgl_ply(two_voxels());
  EXPECT_NE(error_of([&] { scene::load_gaussian_scene(path); }).find("sparse-voxel PLY"), std::string::npos);
  EXPECT_TRUE(scene::is_voxel_scene_file(path));
  fs::remove(path);
}

TEST(VoxelFile, SaveLoadAndRecognise) {
  const fs::path path = fs::temp_directory_path() / "lfd_voxel_io_test.voxels";
  scene::save_voxel_scene(path, two_voxels());
  EXPECT_TRUE(scene::is_voxel_scene_file(path));
  expect_same(scene::load_voxel_scene(path), two_voxels());
  fs::remove(path);
  EXPECT_FALSE(scene::is_voxel_scene_file(fs::path(LFD_TEST_DATA_DIR) / "scenes" / "three-points.ply"));
}

}  // namespace
}  // namespace lfd::scene
