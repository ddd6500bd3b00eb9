// A moving scene: a two-frame sequence records two different frames, each equal to
// `lfd render --frame K` of its own frame; a missing or corrupt frame is refused with no video.
#include <fstream>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "render/image_metrics.hpp"
#include "scene/gaussian_io.hpp"
#include "scene/ply_writer.hpp"
#include "tests/record/record_test_support.hpp"
#include "util/atomic_file.hpp"

namespace lfd {
namespace {

namespace fs = std::filesystem;

// The demo scene as frame 0, and as frame 1 with every Gaussian's colour turned (red <-> blue) and
// moved a little to the right: the same framing, a different picture.
void write_two_frames(const fs::path& dir) {
  fs::copy_file(test::kRecordScene, dir / "s_0000.ply");
  scene::GaussianScene moved = scene::load_gaussian_scene(test::kRecordScene);
  for (size_t i = 0; i < moved.size(); ++i) {
    moved.positions[i][0] += 0.05f;
    float* dc = moved.sh.data() + i * size_t(moved.sh_coeffs()) * 3;
    std::swap(dc[0], dc[2]);
  }
  write_text_atomic(dir / "s_0001.ply", scene::encode_ply(moved));
}

TEST(RecordSequence, TwoFramesRecordTwoDifferentFramesEachItsOwnRender) {
  const fs::path dir = test::temp_dir("record_sequence");
  write_two_frames(dir);
  const std::string pattern = (dir / "s_%04d.ply").string();
  const auto r = test::run_lfd("record --scene " + pattern + test::kRecordSmall + "--fps 2 --save-cameras " +
                               (dir / "cams").string() + " --out " + (dir / "seq.mp4").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const test::DecodedVideo video = test::decode_video(dir / "seq_qs2x2a1.5.mp4");
  ASSERT_EQ(video.frames.size(), 2u) << "one video frame per scene frame";
  std::vector<Image8> renders;
  for (int k = 0; k < 2; ++k) {
    const fs::path out = dir / fmt::format("frame{}.png", k);
    const auto rr = test::run_lfd("render --scene " + pattern + " --frame " + std::to_string(k) + " --camera " +
                                  (dir / "cams" / fmt::format("frame_{:05d}.json", k)).string() + test::kRecordSmall +
                                  "--out " + out.string());
    ASSERT_EQ(rr.exit_code, 0) << rr.output;
    renders.push_back(read_image(dir / fmt::format("frame{}_qs2x2a1.5.png", k), 3));
  }
  const auto psnr = [](const Image8& a, const Image8& b) { return render::psnr(to_float(a), to_float(b)); };
  EXPECT_LT(psnr(renders[0], renders[1]), 30.0) << "the two frames differ";
  for (int k = 0; k < 2; ++k) {
    // The bars of record_cli_test.cpp: the luma (the codec's loss) and RGB (4:2:0 too).
    EXPECT_GE(psnr(video.luma[k], test::bt709_luma(renders[k])), 35.0) << "frame " << k;
    EXPECT_GE(psnr(video.frames[k], renders[k]), 23.0) << "frame " << k;
    EXPECT_GT(psnr(video.frames[k], renders[k]), psnr(video.frames[k], renders[1 - k]) + 5.0) << "frame " << k;
  }
}

TEST(RecordSequence, AMissingOrCorruptFrameIsRefusedWithNoVideo) {
  const fs::path dir = test::temp_dir("record_sequence_bad");
  write_two_frames(dir);
  fs::rename(dir / "s_0001.ply", dir / "s_0002.ply");  // a gap: frame 1 missing
  auto r = test::run_lfd("record --scene " + (dir / "s_%04d.ply").string() + test::kRecordSmall + "--out " +
                         (dir / "bad.mp4").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("frame 1 (s_0001.ply) is missing"), std::string::npos) << r.output;
  EXPECT_TRUE(test::files_ending(dir, ".mp4").empty());
  // A corrupt frame is found when it is read, after frame 0 is encoded: the partial video goes.
  write_text_atomic(dir / "s_0001.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 99\nend_header\n");
  r = test::run_lfd("record --scene " + (dir / "s_%04d.ply").string() + test::kRecordSmall + "--out " +
                    (dir / "bad.mp4").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("s_0001.ply"), std::string::npos) << r.output;
  EXPECT_TRUE(test::files_ending(dir, ".mp4").empty()) << r.output;
}

}  // namespace
}  // namespace lfd
