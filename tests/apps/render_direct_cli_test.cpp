// `lfd render --direct` end to end (docs/rendering.md "Direct panel rendering"): the panel straight
// from the sweeping planes, no quilt file; it is the quilt path's panel where views agree (close in
// PSNR), and every option that needs a quilt, or a missing display or --panel, is one line and exit
// 2 with nothing written.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/support/run_lfd.hpp"
#include "tests/test_data.hpp"
#include "util/atomic_file.hpp"
#include "util/image.hpp"

namespace lfd {
namespace {

namespace fs = std::filesystem;

const std::string kScene = (test::project_data() / "scenes" / "demo.ply").string();
const std::string kDisplay = (test::project_data() / "displays" / "portrait.visual.json").string();
const std::string kSmall = " --size 96x128 --views 16 --chunks 16 ";

// PSNR of two 8-bit images in dB (peak 255).
double psnr8(const Image8& a, const Image8& b) {
  double sum = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    const double d = double(a.pixels[i]) - double(b.pixels[i]);
    sum += d * d;
  }
  const double mse = sum / double(a.pixels.size());
  return 10.0 * std::log10(255.0 * 255.0 / std::max(mse, 1e-12));
}

TEST(RenderDirectCli, WritesThePanelWithoutAQuiltCloseToTheQuiltPath) {
  const fs::path dir = test::temp_dir("render_direct");
  const std::string direct = (dir / "direct.png").string(), via_quilt = (dir / "via_quilt.png").string();
  const auto r = test::run_lfd("render --scene " + kScene + " --calibration " + kDisplay + kSmall + " --panel " +
                               direct + " --direct");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("direct: no quilt"), std::string::npos) << r.output;
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir)) files += e.is_regular_file();
  EXPECT_EQ(files, 1) << "only the panel is written";
  const auto q = test::run_lfd("render --scene " + kScene + " --calibration " + kDisplay + kSmall + " --panel " +
                               via_quilt + " --out " + (dir / "q.png").string());
  ASSERT_EQ(q.exit_code, 0) << q.output;
  const Image8 a = read_image(direct, 3), b = read_image(via_quilt, 3);
  ASSERT_EQ(a.width, 1536);
  ASSERT_EQ(a.height, 2048);
  ASSERT_EQ(b.width, a.width);
  ASSERT_EQ(b.height, a.height);
  // The same planes and lens; they differ where the quilt path rounds a subpixel's view.
  EXPECT_GT(psnr8(a, b), 25.0);
}

TEST(RenderDirectCli, OptionsThatDoNotApplyAreOneLineAndExitTwo) {
  const fs::path dir = test::temp_dir("render_direct_bad");
  const std::string panel = " --panel " + (dir / "p.png").string();
  const std::string base = "render --scene " + kScene + kSmall;
  const std::pair<std::string, std::string> cases[] = {
      {base + panel + " --direct", "--direct: needs the display"},
      {base + " --calibration " + kDisplay + " --direct", "--direct: needs --panel"},
      {base + " --calibration " + kDisplay + panel + " --direct --blend linear", "--blend: a quilt option"},
      {base + " --calibration " + kDisplay + panel + " --direct --out q.png", "--out: a quilt option"},
      {base + " --calibration " + kDisplay + panel + " --direct --view 3", "--view: a quilt option"},
      {base + " --calibration " + kDisplay + panel + " --direct --cols 4 --rows 4", "--cols: a quilt option"},
      {base + " --calibration " + kDisplay + panel + " --direct --method per-view", "not --method per-view"},
      {base + " --calibration " + kDisplay + panel, "--out: required"},
  };
  for (const auto& [args, says] : cases) {
    const auto r = test::run_lfd(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(says), std::string::npos) << args << "\n" << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  }
  EXPECT_TRUE(fs::is_empty(dir)) << "nothing written";
}

// `lfd bench direct` on a small run: both sides timed, the quilt's bytes, the three PSNRs against
// the reference, in the table and the JSON.
TEST(BenchDirectCli, ATinyRunReportsBothSidesAndTheQuality) {
  const fs::path dir = test::temp_dir("bench_direct");
  const std::string json = (dir / "direct.json").string();
  const auto r = test::run_lfd("bench direct --calibration " + kDisplay +
                               " --generated 2000 --view-height 64 --chunks 4,8 --runs 1 --warmup 0 "
                               "--reference-views 8 --json " + json);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("| N_chunk | swizzle [s]"), std::string::npos) << r.output;
  const nlohmann::json j = nlohmann::json::parse(read_text_file(json));
  ASSERT_EQ(j["tables"].size(), 1u);
  const auto& rows = j["tables"][0]["rows"];
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& row : rows) {
    EXPECT_GT(row["direct_pass_seconds"]["median"].get<double>(), 0.0);
    EXPECT_GT(row["after_planes_quilt_seconds"]["median"].get<double>(), 0.0);
    EXPECT_GT(row["quilt_bytes"].get<double>(), 0.0);
    for (const char* psnr : {"psnr_direct_db", "psnr_quilt_nearest_db", "psnr_quilt_linear_db"})
      EXPECT_GT(row[psnr].get<double>(), 15.0) << psnr;
  }
  const auto bad = test::run_lfd("bench direct --calibration " + kDisplay + " --chunks 0");
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("direct benchmark: chunks: 0 is outside"), std::string::npos) << bad.output;
}

// `lfd bench direct --direct-kernel`: the scalar and the AVX2 sampling loops give the same panel
// (render/plane_samples.hpp), so the same PSNR to the last digit; a kernel name it does not know
// is refused with one line and exit 2.
TEST(BenchDirectCli, BothSamplingKernelsGiveTheSamePanel) {
  const fs::path dir = test::temp_dir("bench_direct_kernel");
  std::map<std::string, double> psnr;
  for (const std::string kernel : {"scalar", "avx2"}) {
    const std::string json = (dir / (kernel + ".json")).string();
    const auto r = test::run_lfd("bench direct --calibration " + kDisplay +
                                 " --generated 2000 --view-height 64 --chunks 16 --runs 1 --warmup 0 "
                                 "--reference-views 8 --direct-kernel " + kernel + " --json " + json);
    if (kernel == "avx2" && r.exit_code == 2 && r.output.find("this CPU has no AVX2") != std::string::npos) continue;
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const nlohmann::json j = nlohmann::json::parse(read_text_file(json));
    EXPECT_EQ(j["direct_kernel"], kernel);
    psnr[kernel] = j["tables"][0]["rows"][0]["psnr_direct_db"].get<double>();
  }
  ASSERT_TRUE(psnr.count("scalar"));
  if (psnr.count("avx2")) {
    EXPECT_EQ(psnr["scalar"], psnr["avx2"]);
  }
  const auto bad = test::run_lfd("bench direct --calibration " + kDisplay + " --direct-kernel sse9");
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("--direct-kernel"), std::string::npos) << bad.output;
}

// `lfd bench direct --method v2lf`: the direct pass on V2LF planes of a generated voxel tabletop,
// against the quilt path and the per-view voxel reference; the other method's scene option is
// refused with one line and exit 2.
TEST(BenchDirectCli, V2lfRunsOnVoxelScenes) {
  const fs::path dir = test::temp_dir("bench_direct_v2lf");
  const std::string json = (dir / "direct.json").string();
  const auto r = test::run_lfd("bench direct --method v2lf --voxel-level 5 --calibration " + kDisplay +
                               " --view-height 64 --chunks 8 --runs 1 --warmup 0 --reference-views 8 --json " + json);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("generated voxel tabletop (level 5)"), std::string::npos) << r.output;
  const nlohmann::json j = nlohmann::json::parse(read_text_file(json));
  ASSERT_EQ(j["tables"].size(), 1u);
  EXPECT_EQ(j["tables"][0]["method"], "V2LF");
  const auto& row = j["tables"][0]["rows"][0];
  EXPECT_GT(row["direct_pass_seconds"]["median"].get<double>(), 0.0);
  for (const char* psnr : {"psnr_direct_db", "psnr_quilt_nearest_db", "psnr_quilt_linear_db"})
    EXPECT_GT(row[psnr].get<double>(), 10.0) << psnr;
  const std::pair<std::string, std::string> cases[] = {
      {"bench direct --voxel-level 5", "--voxel-level: applies to --method v2lf only"},
      {"bench direct --method v2lf --generated 1000", "--generated: applies to --method g2lf only"},
      {"bench direct --method v2lf --voxel-level 99", "voxel generator options"},
  };
  for (const auto& [args, says] : cases) {
    const auto bad = test::run_lfd(args);
    EXPECT_EQ(bad.exit_code, 2) << args << "\n" << bad.output;
    EXPECT_NE(bad.output.find(says), std::string::npos) << args << "\n" << bad.output;
    EXPECT_EQ(std::count(bad.output.begin(), bad.output.end(), '\n'), 1) << bad.output;
  }
}

}  // namespace
}  // namespace lfd
