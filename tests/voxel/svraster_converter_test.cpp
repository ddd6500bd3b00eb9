// scripts/svraster_to_voxels.py: a synthetic SVRaster checkpoint (tests/voxel/svraster_fixture.py,
// plain and quantized) converted and read back by the C++ reader. Skips without python3 + numpy.
#include <gtest/gtest.h>

#include <cstdlib>
#include <set>
#include <string>
#include <tuple>

#include "tests/test_data.hpp"
#include "scene/voxel_io.hpp"

namespace lfd::voxel {
namespace {

namespace fs = std::filesystem;

// A python3 that imports numpy, or empty.
std::string python_with_numpy() {
  for (std::string python : {"python3", "/usr/bin/python3"})
    if (std::system((python + " -c 'import numpy' > /dev/null 2>&1").c_str()) == 0) return python;
  return {};
}

// The fixture's octree: the root's children but (1,1,1), its children but (2,2,2), and those.
std::set<std::tuple<uint32_t, uint32_t, uint32_t, int>> fixture_leaves() {
  std::set<std::tuple<uint32_t, uint32_t, uint32_t, int>> out;
  for (uint32_t level = 1; level <= 3; ++level) {
    const uint32_t lo = 2u * (level - 1u), split = level == 1 ? 1u : level == 2 ? 2u : 99u;
    for (uint32_t i = lo; i < lo + 2; ++i)
      for (uint32_t j = lo; j < lo + 2; ++j)
        for (uint32_t k = lo; k < lo + 2; ++k)
          if (!(i == split && j == split && k == split)) out.emplace(i, j, k, int(level));
  }
  return out;
}

void expect_fixture(const scene::VoxelScene& v, const std::string& which) {
  SCOPED_TRACE(which);
  EXPECT_EQ(v.scene_center, glm::vec3(0.5f, -1.0f, 2.0f));
  EXPECT_EQ(v.scene_extent, 4.0f);
  EXPECT_EQ(v.sh_degree, 2) << "active_sh_degree, not the config's 3";
  EXPECT_EQ(v.supersampling, 1.25f);
  EXPECT_EQ(v.samples_per_voxel, 2);
  EXPECT_EQ(v.background, glm::vec3(1.0f)) << "white_background";
  ASSERT_EQ(v.size(), 22u);
  std::set<std::tuple<uint32_t, uint32_t, uint32_t, int>> seen;
  for (size_t i = 0; i < v.size(); ++i) {
    seen.emplace(v.octree_index[i].x, v.octree_index[i].y, v.octree_index[i].z, int(v.level[i]));
    const glm::vec3 lo = v.voxel_min(i);
    for (int c = 0; c < 8; ++c) {
      // Each corner holds the fixture's field at its world position: the octpath decoding, the
      // grid point numbering and the corner order all have to be right.
      const glm::vec3 p = lo + v.voxel_size(i) * glm::vec3(c >> 2 & 1, c >> 1 & 1, c & 1);
      EXPECT_NEAR(v.corner_density[i][size_t(c)], 1.0f + 2.0f * p.x - 3.0f * p.y + 0.5f * p.z, 1e-5f) << i << " " << c;
    }
    const float* sh = v.voxel_sh(i);
    const glm::vec3 centre = v.voxel_center(i);
    for (int a = 0; a < 3; ++a) EXPECT_FLOAT_EQ(sh[a], centre[a]) << "_sh0 is the centre";
    for (int k = 1; k < 9; ++k)
      for (int ch = 0; ch < 3; ++ch)
        EXPECT_NEAR(sh[3 * k + ch], 0.01f * float(k) + 0.1f * float(ch) + float(v.level[i]), 1e-6f);
  }
  EXPECT_EQ(seen, fixture_leaves());
}

TEST(SvrasterConverter, SyntheticCheckpointRoundTripsThroughTheReader) {
  const std::string python = python_with_numpy();
  if (python.empty()) GTEST_SKIP() << "no python3 with numpy";
  const fs::path dir = test::temp_dir("svraster_converter");
  const std::string command = python + " " + (fs::path(LFD_SOURCE_DIR) / "tests/voxel/svraster_fixture.py").string() +
                              " " + (fs::path(LFD_SOURCE_DIR) / "scripts/svraster_to_voxels.py").string() + " " +
                              dir.string();
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  expect_fixture(scene::load_voxel_scene(dir / "plain.voxels"), "plain");
  expect_fixture(scene::load_voxel_scene(dir / "quantized.voxels"), "quantized");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace lfd::voxel
