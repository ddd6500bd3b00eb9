// `lfd record` end to end: a turntable and a keyframed path recorded, decoded back with FFmpeg,
// each frame equal to `lfd render --camera` of the camera it saved (within the codec's loss), in
// order, with the right count, rate and name; a nerfstudio pose renders the view it describes;
// segments join into the whole; Ctrl-C leaves a playable video.
#include <algorithm>
#include <cmath>
#include <fstream>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "display/display_quilt.hpp"
#include "lightfield/scene_framing.hpp"
#include "render/camera_json.hpp"
#include "render/image_metrics.hpp"
#include "scene/scene.hpp"
#include "tests/record/record_test_support.hpp"
#include "util/atomic_file.hpp"

namespace lfd {
namespace {

namespace fs = std::filesystem;

// Measured at the default quality (CRF 18) on these 96x64 quilts (docs/record.md "Tests"): the
// luma (the codec's loss) 36.8-38.2 dB against the frame's own render; RGB 25.7-26.8 dB, as
// 4:2:0 keeps colour at half resolution and these 48x32 views are nearly all detail.
constexpr double kMinLumaPsnrDb = 35.0;
constexpr double kMinRgbPsnrDb = 23.0;

double psnr(const Image8& a, const Image8& b) { return render::psnr(to_float(a), to_float(b)); }

// Every decoded frame matches the render of its own saved camera, and better than any other's.
void expect_frames_are_their_renders(const test::DecodedVideo& video, const fs::path& cameras, const fs::path& dir,
                                     int frames) {
  ASSERT_EQ(int(video.frames.size()), frames);
  std::vector<Image8> renders;
  for (int i = 0; i < frames; ++i)
    renders.push_back(test::render_saved_camera(cameras / fmt::format("frame_{:05d}.json", i), dir));
  for (int i = 0; i < frames; ++i) {
    const double own = psnr(video.frames[i], renders[i]);
    EXPECT_GE(psnr(video.luma[i], test::bt709_luma(renders[i])), kMinLumaPsnrDb) << "frame " << i;
    EXPECT_GE(own, kMinRgbPsnrDb) << "frame " << i;
    for (int j = 0; j < frames; ++j) {
      if (j != i) EXPECT_GT(own, psnr(video.frames[i], renders[j])) << "frame " << i << " looks like frame " << j;
    }
  }
}

TEST(Record, ATurntableIsItsFramesRendersInOrderAtItsRate) {
  const fs::path dir = test::temp_dir("record_turntable");
  const auto r = test::run_lfd("record --scene " + test::kRecordScene + test::kRecordSmall +
                               "--path turntable --frames 4 --fps 12 --save-cameras " + (dir / "cams").string() +
                               " --out " + (dir / "spin.mp4").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const fs::path video = dir / "spin_qs2x2a1.5.mp4";
  ASSERT_TRUE(fs::exists(video)) << r.output;
  EXPECT_TRUE(test::files_ending(dir, ".partial.mp4").empty());
  const test::DecodedVideo decoded = test::decode_video(video);
  EXPECT_EQ(decoded.info.width, 96);
  EXPECT_EQ(decoded.info.height, 64);
  EXPECT_EQ(decoded.info.codec, "h264");
  EXPECT_NEAR(decoded.info.frame_rate, 12.0, 1e-6);
  expect_frames_are_their_renders(decoded, dir / "cams", dir, 4);
  // A quarter turn per frame about the framed focal point and its up axis: the focus, the
  // distance and the height stay; the offsets across the axis are at right angles.
  const render::CameraSpec a = render::read_camera_json(dir / "cams" / "frame_00000.json");
  const render::CameraSpec b = render::read_camera_json(dir / "cams" / "frame_00001.json");
  const glm::vec3 up = glm::normalize(a.up), da = a.position - a.look_at, db = b.position - b.look_at;
  EXPECT_NEAR(glm::length(a.look_at - b.look_at), 0.0f, 1e-4f);
  EXPECT_NEAR(glm::length(da), glm::length(db), 1e-4f);
  EXPECT_NEAR(glm::dot(da, up), glm::dot(db, up), 1e-4f);
  EXPECT_NEAR(glm::dot(da - glm::dot(da, up) * up, db - glm::dot(db, up) * up), 0.0f, 1e-3f);
}

TEST(Record, AKeyframedPathIsItsFramesRenders) {
  const fs::path dir = test::temp_dir("record_keyframes");
  const auto framing = lightfield::scene_framing(scene::load_scene(test::kRecordScene), render::kDefaultFovYDeg, 0.0f, 1.5f);
  const glm::vec3 side = glm::normalize(glm::cross(framing.look_at - framing.position, framing.up)) *
                         (0.3f * glm::length(framing.look_at - framing.position));
  const auto key = [&](double t, glm::vec3 p, float fov) {
    return fmt::format(R"({{"time_s": {}, "position": [{}, {}, {}], "look_at": [{}, {}, {}], "up": [{}, {}, {}], "fov_y_deg": {}}})",
                       t, p.x, p.y, p.z, framing.look_at.x, framing.look_at.y, framing.look_at.z, framing.up.x,
                       framing.up.y, framing.up.z, fov);
  };
  std::ofstream(dir / "path.json") << "{\"keyframes\": [" << key(0, framing.position - side, 40) << ", "
                                   << key(0.5, framing.position, 30) << ", " << key(1.0, framing.position + side, 40)
                                   << "]}";
  const auto r = test::run_lfd("record --scene " + test::kRecordScene + test::kRecordSmall + "--path " +
                               (dir / "path.json").string() + " --fps 4 --save-cameras " + (dir / "cams").string() +
                               " --out " + (dir / "path.mp4").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const test::DecodedVideo decoded = test::decode_video(dir / "path_qs2x2a1.5.mp4");
  EXPECT_NEAR(decoded.info.frame_rate, 4.0, 1e-6);
  expect_frames_are_their_renders(decoded, dir / "cams", dir, 5);  // 1 s at 4 fps, both ends
  // The middle frame is the middle keyframe.
  const render::CameraSpec mid = render::read_camera_json(dir / "cams" / "frame_00002.json");
  EXPECT_NEAR(glm::length(mid.position - framing.position), 0.0f, 1e-4f);
  EXPECT_NEAR(mid.fov_y_deg, 30.0f, 1e-4f);
}

TEST(Record, OnGlEachFrameIsTheGlRenderOfItsCamera) {
  // The GL renderer (llvmpipe here, as every GL test) records what `lfd render --backend gl` renders.
  // At CRF 8: the turntable's back view loses 33.0 dB of luma at the default CRF 18 (the codec,
  // not the renderer: it passes the 35 dB bar at CRF 8).
  const fs::path dir = test::temp_dir("record_gl");
  const std::string gl = test::kRecordSmall + "--backend gl ";
  const auto r = test::run_lfd("record --scene " + test::kRecordScene + gl + "--path turntable --frames 2 --quality 8 --save-cameras " +
                               (dir / "cams").string() + " --out " + (dir / "gl.mp4").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const test::DecodedVideo decoded = test::decode_video(dir / "gl_qs2x2a1.5.mp4");
  ASSERT_EQ(decoded.frames.size(), 2u);
  for (int i = 0; i < 2; ++i) {
    const Image8 render = test::render_saved_camera(dir / "cams" / fmt::format("frame_{:05d}.json", i), dir, gl);
    EXPECT_GE(psnr(decoded.luma[size_t(i)], test::bt709_luma(render)), kMinLumaPsnrDb) << "frame " << i;
  }
}

TEST(Record, ANerfstudioPoseRendersTheViewItDescribes) {
  // The framing's camera written as nerfstudio's camera_to_world (x right, y up, looking down -z).
  const fs::path dir = test::temp_dir("record_nerfstudio");
  const auto framing = lightfield::scene_framing(scene::load_scene(test::kRecordScene), render::kDefaultFovYDeg, 25.0f, 1.5f);
  const glm::vec3 back = glm::normalize(framing.position - framing.look_at);
  const glm::vec3 right = glm::normalize(glm::cross(framing.up, back)), up = glm::cross(back, right);
  const glm::vec3& p = framing.position;
  std::ofstream(dir / "camera_path.json") << fmt::format(
      R"({{"fps": 10, "camera_path": [{{"camera_to_world": [{}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, 0, 0, 0, 1], "fov": {}}}]}})",
      right.x, up.x, back.x, p.x, right.y, up.y, back.y, p.y, right.z, up.z, back.z, p.z, framing.fov_y_deg);
  render::CameraSpec expected = framing;
  expected.width = 48;
  expected.height = 32;
  std::ofstream(dir / "expected.json") << render::camera_json_text(expected);
  const auto r = test::run_lfd("record --scene " + test::kRecordScene + test::kRecordSmall + "--path " +
                               (dir / "camera_path.json").string() + " --out " + (dir / "ns.mp4").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const test::DecodedVideo decoded = test::decode_video(dir / "ns_qs2x2a1.5.mp4");
  ASSERT_EQ(decoded.frames.size(), 1u);
  EXPECT_NEAR(decoded.info.frame_rate, 10.0, 1e-6) << "the path's own fps";
  const Image8 expected_quilt = test::render_saved_camera(dir / "expected.json", dir);
  EXPECT_GE(psnr(decoded.luma[0], test::bt709_luma(expected_quilt)), kMinLumaPsnrDb);
  EXPECT_GE(psnr(decoded.frames[0], expected_quilt), kMinRgbPsnrDb);
}

TEST(Record, SegmentsJoinIntoTheWholeWithoutReencoding) {
  const fs::path dir = test::temp_dir("record_segments");
  for (const char* range : {"0-1", "2-3"}) {
    const auto r = test::run_lfd("record --scene " + test::kRecordScene + test::kRecordSmall +
                                 "--path turntable --seconds 0.4 --fps 10 --frames " + range + " --save-cameras " +
                                 (dir / "cams").string() + " --out " + (dir / "s.mp4").string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  const fs::path a = dir / "s_qs2x2a1.5_f0000-0001.mp4", b = dir / "s_qs2x2a1.5_f0002-0003.mp4";
  ASSERT_TRUE(fs::exists(a) && fs::exists(b));
  const auto c = test::run_lfd("record --concat " + a.string() + " " + b.string() + " --out " + (dir / "all.mp4").string());
  ASSERT_EQ(c.exit_code, 0) << c.output;
  const test::DecodedVideo joined = test::decode_video(dir / "all_qs2x2a1.5.mp4");
  EXPECT_NEAR(joined.info.frame_rate, 10.0, 1e-6);
  expect_frames_are_their_renders(joined, dir / "cams", dir, 4);
  // Not re-encoded: the joined file is the segments' packets (sizes add up within the headers).
  EXPECT_LT(std::abs(double(fs::file_size(dir / "all_qs2x2a1.5.mp4")) - double(fs::file_size(a) + fs::file_size(b))),
            0.2 * double(fs::file_size(a) + fs::file_size(b)));
}

// The 16" landscape Gen3 unit at a tenth of its pixels, DPI and lens pitch (384x216).
fs::path small_gen3(const fs::path& dir) {
  std::string text = read_text_file(test::project_data() / "displays" / "16in-landscape-gen3.visual.json");
  const auto set = [&](const std::string& field, const std::string& value) {
    const size_t at = text.find("\"" + field + "\"");
    const size_t v = text.find("\"value\":", at) + 8, end = text.find_first_of("\n}", v);
    text.replace(v, end - v, " " + value);
  };
  set("screenW", "384");
  set("screenH", "216");
  set("DPI", "28.3");
  set("pitch", "4.472");
  write_text_atomic(dir / "gen3.visual.json", text);
  return dir / "gen3.visual.json";
}

TEST(Record, HevcOddSizesAndThePanelVideo) {
  const fs::path dir = test::temp_dir("record_hevc_panel");
  const auto r = test::run_lfd("record --scene " + test::kRecordScene + " --calibration " +
                               small_gen3(dir).string() + " --views 6 --cols 2 --rows 3 --size 48x27 --chunks 8 "
                               "--frames 2 --codec hevc --panel " + (dir / "panel.mp4").string() + " --out " +
                               (dir / "h.mp4").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // 27 rows at 16:9 are 48 columns: the quilt names the panel's 1.7778; its 81 rows are padded
  // to 82 with a row at the top that no tile reads (floor(82 / 3) = 27).
  const test::DecodedVideo quilt = test::decode_video(dir / "h_qs2x3a1.7778.mp4");
  EXPECT_EQ(quilt.info.codec, "hevc");
  EXPECT_EQ(quilt.frames.size(), 2u);
  EXPECT_EQ(quilt.info.width, 96);
  EXPECT_EQ(quilt.info.height, 82);
  const test::DecodedVideo panel = test::decode_video(dir / "panel.mp4");
  EXPECT_EQ(panel.frames.size(), 2u);
  EXPECT_EQ(panel.info.width, 384);
  EXPECT_EQ(panel.info.height, 216);
}

// Bad input: one line naming the file and the field, exit 2, and no video at all.
void expect_refused(const std::string& args, const fs::path& dir, const std::string& says) {
  const auto r = test::run_lfd("record --scene " + test::kRecordScene + test::kRecordSmall + args + " --out " +
                               (dir / "bad.mp4").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(says), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_TRUE(test::files_ending(dir, ".mp4").empty()) << r.output;
}

TEST(Record, BadPathsAndOutputsAreRefusedWithNoVideo) {
  const fs::path dir = test::temp_dir("record_bad");
  write_text_atomic(dir / "nan.json",
                    R"({"camera_path": [{"camera_to_world": [1, 0, 0, 0, 0, 1, 0, NaN, 0, 0, 1, 4, 0, 0, 0, 1], "fov": 40}]})");
  expect_refused("--path " + (dir / "nan.json").string(), dir,
                 (dir / "nan.json").string() + ": camera_path[0].camera_to_world: must be finite");
  write_text_atomic(dir / "size.json", R"({"camera_path": [{"camera_to_world": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 4], "fov": 40}]})");
  expect_refused("--path " + (dir / "size.json").string(), dir,
                 (dir / "size.json").string() + ": camera_path[0].camera_to_world: must be 16 numbers (a 4x4 matrix)");
  write_text_atomic(dir / "empty.json", R"({"keyframes": []})");
  expect_refused("--path " + (dir / "empty.json").string(), dir, (dir / "empty.json").string() + ": keyframes: none");
  expect_refused("--path orbit:0", dir, "--path: 'orbit:0'");
  expect_refused("--frames 3-9 --seconds 0.2 --fps 10", dir, "--frames: 3-9");
  // An output under a regular file cannot be created.
  write_text_atomic(dir / "file", "x");
  const auto r = test::run_lfd("record --scene " + test::kRecordScene + test::kRecordSmall + "--frames 1 --out " +
                               (dir / "file" / "v.mp4").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find((dir / "file").string()), std::string::npos) << r.output;
  EXPECT_TRUE(test::files_ending(dir, ".mp4").empty());
}

TEST(Record, CtrlCLeavesAPlayableVideoOfTheFramesDone) {
  // Interrupted once its video exists (the first frame is under way), it finishes that frame,
  // closes the video under its final name and exits 130.
  const fs::path dir = test::temp_dir("record_interrupt");
  const fs::path partial = dir / "long_qs2x2a1.5.partial.mp4";
  const auto r = test::run_command(fmt::format(
      "{} record --scene {} {} --path turntable --frames 500 --out {} 2>&1 & pid=$!; "
      "while [ ! -e {} ] && kill -0 $pid 2>/dev/null; do sleep 0.05; done; kill -INT $pid; wait $pid; echo rc=$?",
      LFD_EXE, test::kRecordScene, test::kRecordSmall, (dir / "long.mp4").string(), partial.string()));
  EXPECT_NE(r.output.find("rc=130"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("interrupted: "), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(partial));
  const test::DecodedVideo decoded = test::decode_video(dir / "long_qs2x2a1.5.mp4");
  EXPECT_GE(decoded.frames.size(), 1u);
  EXPECT_LT(decoded.frames.size(), 500u);
}

TEST(Record, ACrashLeavesAPlayablePartialVideo) {
  // kill -9 (no chance to close the file) once some fragments are written: the partial file is a
  // fragmented MP4 that plays up to its last whole fragment (one per keyframe: every frame at 1 fps;
  // x264 hands its first packets over some frames late). The header is 782 bytes, a fragment ~5 KB.
  const fs::path dir = test::temp_dir("record_crash");
  const fs::path partial = dir / "crash_qs2x2a1.5.partial.mp4";
  const auto r = test::run_command(fmt::format(
      "{} record --scene {} {} --path turntable --frames 500 --fps 1 --out {} >/dev/null 2>&1 & pid=$!; "
      "while [ \"$(stat -c %s {} 2>/dev/null || echo 0)\" -lt 2000 ] && kill -0 $pid 2>/dev/null; do sleep 0.05; done; "
      "kill -9 $pid; wait $pid; echo rc=$?",
      LFD_EXE, test::kRecordScene, test::kRecordSmall, (dir / "crash.mp4").string(), partial.string()));
  EXPECT_NE(r.output.find("rc=137"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "crash_qs2x2a1.5.mp4")) << "nothing under the final name";
  const test::DecodedVideo decoded = test::decode_video(partial);
  EXPECT_GE(decoded.frames.size(), 1u);
  EXPECT_LT(decoded.frames.size(), 500u);
}

TEST(Record, TheBenchmarkReportsBothSidesOfEachRenderer) {
  // A tiny run on the CPU: the JSON has both rates per run and the encoder's share (no timing
  // is asserted; lfd bench record measures, docs/record.md "Speed").
  const fs::path dir = test::temp_dir("record_bench");
  const auto r = test::run_lfd("bench record --backend cpu --size 32 --views 4 --frames 2 --runs 2 --json " +
                               (dir / "b.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = nlohmann::json::parse(read_text_file(dir / "b.json"));
  ASSERT_EQ(j["rows"].size(), 1u);
  const auto& row = j["rows"][0];
  EXPECT_EQ(row["renderer"], "g2lf on the CPU");
  EXPECT_EQ(row["render_frames_per_s"]["samples"].size(), 2u);
  EXPECT_EQ(row["record_frames_per_s"]["samples"].size(), 2u);
  EXPECT_GT(row["record_frames_per_s"]["median"].get<double>(), 0.0);
  EXPECT_LT(row["encoder_share"].get<double>(), 1.0);
  EXPECT_EQ(row["quilt_width"], 64);
}

}  // namespace
}  // namespace lfd
