// Scene sequences (scene/scene_sequence.hpp): a %0Nd pattern from the lowest number present, a
// folder in name order, a list file; a gap or a missing listed file names the file and the frame.
#include "scene/scene_sequence.hpp"

#include <fstream>

#include <gtest/gtest.h>

#include "tests/test_data.hpp"
#include "util/error.hpp"

namespace lfd::scene {
namespace {

namespace fs = std::filesystem;

void touch(const fs::path& p) { std::ofstream(p) << "x"; }

std::string error_of(const std::string& spec) {
  try {
    find_scene_sequence(spec);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SceneSequence, APatternStartsAtTheLowestNumberPresent) {
  const fs::path dir = test::temp_dir("scene_sequence_pattern");
  for (int n : {7, 8, 9}) touch(dir / ("m_000" + std::to_string(n) + ".sog"));
  touch(dir / "m_7.sog");      // another width: not this pattern's
  touch(dir / "other_0001.sog");
  const std::string spec = (dir / "m_%04d.sog").string();
  EXPECT_TRUE(is_scene_sequence(spec));
  const SceneSequence s = find_scene_sequence(spec);
  ASSERT_EQ(s.frames.size(), 3u);
  EXPECT_EQ(s.frames[0].filename(), "m_0007.sog");
  EXPECT_EQ(s.frames[2].filename(), "m_0009.sog");
  // %d takes any width: m_7 and m_0007 are both frame 7.
  EXPECT_NE(error_of((dir / "m_%d.sog").string()).find(": two files are frame 7 ("), std::string::npos);
  fs::remove(dir / "m_7.sog");
  EXPECT_EQ(find_scene_sequence((dir / "m_%d.sog").string()).frames.size(), 3u);
}

TEST(SceneSequence, AGapIsAMissingFrame) {
  const fs::path dir = test::temp_dir("scene_sequence_gap");
  for (const char* name : {"f_01.ply", "f_02.ply", "f_04.ply"}) touch(dir / name);
  const std::string spec = (dir / "f_%02d.ply").string();
  EXPECT_EQ(error_of(spec), spec + ": frame 3 (f_03.ply) is missing (frames 1..4 present)");
  EXPECT_EQ(error_of((dir / "g_%02d.ply").string()), (dir / "g_%02d.ply").string() + ": no frame matches the pattern");
}

TEST(SceneSequence, AFolderInNameOrderAndAListFile) {
  const fs::path dir = test::temp_dir("scene_sequence_folder");
  fs::create_directories(dir / "frames");
  for (const char* name : {"b.ply", "a.ply", "c.ply"}) touch(dir / "frames" / name);
  const SceneSequence folder = find_scene_sequence((dir / "frames").string());
  ASSERT_EQ(folder.frames.size(), 3u);
  EXPECT_EQ(folder.frames[0].filename(), "a.ply");
  EXPECT_EQ(folder.frames[2].filename(), "c.ply");
  std::ofstream(dir / "list.txt") << "# two frames\nframes/c.ply\n\nframes/a.ply\r\n";
  const SceneSequence list = find_scene_sequence((dir / "list.txt").string());
  ASSERT_EQ(list.frames.size(), 2u);
  EXPECT_EQ(list.frames[0].filename(), "c.ply");
  std::ofstream(dir / "bad.txt") << "frames/a.ply\nframes/zzz.ply\n";
  EXPECT_EQ(error_of((dir / "bad.txt").string()),
            (dir / "bad.txt").string() + ": line 2: '" + (dir / "frames" / "zzz.ply").string() + "' not found");
}

TEST(SceneSequence, OneFileIsNotASequence) {
  EXPECT_FALSE(is_scene_sequence("scene.ply"));
  EXPECT_EQ(find_scene_sequence("scene.ply").frames.size(), 1u);
}

}  // namespace
}  // namespace lfd::scene
