// Moving scenes played in real time (scene/scene_stream.hpp): frames read ahead on a thread, in
// order, looping, memory bounded to the window ahead, a bad frame's error handed to the player.
#include "scene/scene_stream.hpp"

#include <fstream>

#include <gtest/gtest.h>

#include "scene/ply_writer.hpp"
#include "tests/test_data.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"

namespace lfd::scene {
namespace {

namespace fs = std::filesystem;

// Frame k: k + 1 Gaussians (so a frame says which it is by its size).
SceneSequence write_frames(const fs::path& dir, int count) {
  SceneSequence s{(dir / "f_%02d.ply").string(), {}};
  for (int k = 0; k < count; ++k) {
    GaussianScene g;
    for (int i = 0; i <= k; ++i) {
      g.positions.push_back({float(i), 0.0f, 0.0f});
      g.scales.push_back({0.1f, 0.1f, 0.1f});
      g.rotations.push_back({1.0f, 0.0f, 0.0f, 0.0f});
      g.opacities.push_back(0.5f);
      for (int c = 0; c < 3; ++c) g.sh.push_back(0.2f);
    }
    const fs::path path = dir / ("f_0" + std::to_string(k) + ".ply");
    write_text_atomic(path, encode_ply(g));
    s.frames.push_back(path);
  }
  return s;
}

TEST(SceneStream, FramesComeInOrderLoopingWithAtMostTheWindowHeld) {
  const fs::path dir = test::temp_dir("scene_stream");
  SceneStream stream(write_frames(dir, 6), 2);
  for (int round = 0; round < 2; ++round)
    for (int k = 0; k < 6; ++k) {
      const auto frame = stream.frame(k, true);
      ASSERT_TRUE(frame);
      EXPECT_EQ(frame->size(), size_t(k + 1)) << "frame " << k;
      EXPECT_LE(stream.frames_held(), 3) << "the shown frame and 2 ahead";
    }
}

TEST(SceneStream, ABadFrameIsTheErrorOfThatFrameOnly) {
  const fs::path dir = test::temp_dir("scene_stream_bad");
  SceneSequence s = write_frames(dir, 3);
  write_text_atomic(s.frames[1], "ply\nformat nonsense\n");
  SceneStream stream(s, 2);
  EXPECT_TRUE(stream.frame(0, true));
  try {
    stream.frame(1, true);
    FAIL() << "a broken frame was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("f_01.ply"), std::string::npos) << e.what();
  }
  EXPECT_EQ(stream.frame(2, true)->size(), 3u);
}

}  // namespace
}  // namespace lfd::scene
