// Quilt videos: encoded here with libavcodec (media/video_encoder.hpp), decoded back frame by
// frame (count, rate, size, the pictures within encoder loss), sought to the frame shown at a
// time, read from memory as from the file; bad files are one-line errors naming the file. The
// YUV -> RGB coefficients give the known colours of BT.601/709.
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

extern "C" {
#include <libavcodec/avcodec.h>
}

#include "media/quilt_image.hpp"
#include "media/synthetic_quilt.hpp"
#include "media/video_decoder.hpp"
#include "render/image_metrics.hpp"
#include "tests/support/quilt_layouts.hpp"
#include "util/error.hpp"

namespace lfd::media {
namespace {

namespace fs = std::filesystem;

render::QuiltLayout tiny_layout() { return test::quilt_layout(4, 2, 160, 80); }

constexpr int kFrames = 12;

fs::path encoded(const std::string& codec, const std::string& extension) {
  const fs::path path = fs::temp_directory_path() / ("lfd_media_test_" + codec + extension);
  if (!fs::exists(path)) {
    EncoderOptions o;
    o.codec = codec;
    o.frame_rate = 30;
    write_synthetic_quilt_video(path, tiny_layout(), kFrames, o);
  }
  return path;
}

void expect_round_trip(const fs::path& video, const std::string& codec_name) {
  VideoDecoder decoder(video, {true, 2});
  EXPECT_EQ(decoder.info().width, 160);
  EXPECT_EQ(decoder.info().height, 80);
  EXPECT_NEAR(decoder.info().frame_rate, 30.0, 1e-6);
  EXPECT_EQ(decoder.info().codec, codec_name);
  EXPECT_NE(decoder.decode_path().find("software"), std::string::npos) << decoder.decode_path();  // no VA-API here
  int count = 0;
  while (auto frame = decoder.next_frame()) {
    EXPECT_EQ(frame->index, count);
    EXPECT_EQ(frame->matrix, YuvMatrix::kBt709);
    EXPECT_EQ(frame->range, YuvRange::kLimited);
    const double db = render::psnr(to_float(yuv_to_rgb(*frame)), to_float(synthetic_quilt(tiny_layout(), count)));
    EXPECT_GE(db, 28.0) << "frame " << count;
    ++count;
  }
  EXPECT_EQ(count, kFrames);
}

TEST(VideoDecoder, H264RoundTrip) { expect_round_trip(encoded("libx264", ".mp4"), "h264"); }

TEST(VideoDecoder, HevcRoundTrip) {
  if (!avcodec_find_encoder_by_name("libx265")) GTEST_SKIP() << "no libx265 encoder";
  expect_round_trip(encoded("libx265", ".mp4"), "hevc");
}

TEST(VideoDecoder, Vp9WebmRoundTrip) {
  if (!avcodec_find_encoder_by_name("libvpx-vp9")) GTEST_SKIP() << "no libvpx-vp9 encoder";
  expect_round_trip(encoded("libvpx-vp9", ".webm"), "vp9");
}

// The hardware decoders are tried in order (docs/arm.md "Video on small boards"); where one runs
// its name is the path, and where the software decoder runs its name says why each was passed
// over. Without hardware decoding asked for, software with no reasons.
TEST(VideoDecoder, TheDecodePathSaysWhichDecoderRunsAndWhyNotTheHardware) {
  const fs::path video = encoded("libx264", ".mp4");
  const std::string path = VideoDecoder(video, {true, 1}).decode_path();
  if (path.rfind("software (h264, 1 threads", 0) == 0) {
    for (const char* tried : {"; VA-API: ", "; DRM (V4L2 request): ", "; V4L2 M2M: "})
      EXPECT_NE(path.find(tried), std::string::npos) << tried << " in " << path;
  } else {
    EXPECT_TRUE(path == "VA-API" || path == "DRM (V4L2 request)" || path.rfind("V4L2 M2M (h264_v4l2m2m)", 0) == 0)
        << path;
  }
  EXPECT_EQ(VideoDecoder(video, {false, 1}).decode_path(), "software (h264, 1 threads)");
}

TEST(VideoDecoder, SeekGivesTheFrameShownAtThatTime) {
  VideoDecoder decoder(encoded("libx264", ".mp4"), {false, 1});
  for (const auto& [t, index] : std::vector<std::pair<double, int>>{{0.2, 6}, {0.0, 0}, {0.35, 10}, {0.1, 3}, {99, 11}}) {
    decoder.seek(t);
    const auto frame = decoder.next_frame();
    ASSERT_TRUE(frame) << t;
    EXPECT_EQ(frame->index, index) << t;
    const auto after = decoder.next_frame();  // then on in order
    if (index < kFrames - 1) {
      ASSERT_TRUE(after);
      EXPECT_EQ(after->index, index + 1);
    }
  }
}

TEST(VideoDecoder, MemoryInputDecodesAsTheFile) {
  const fs::path video = encoded("libx264", ".mp4");
  VideoDecoder file(video, {false, 1});
  VideoDecoder memory(read_file_bytes(video), "memory.mp4", {false, 1});
  for (int i = 0; i < kFrames; ++i) {
    const auto a = file.next_frame(), b = memory.next_frame();
    ASSERT_TRUE(a && b);
    EXPECT_EQ(yuv_to_rgb(*a).pixels, yuv_to_rgb(*b).pixels);
  }
  EXPECT_FALSE(memory.next_frame());
}

std::string open_error(const fs::path& path) {
  try {
    VideoDecoder decoder(path);
    while (decoder.next_frame()) {
    }
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(VideoDecoder, BadFilesAreErrorsNamingTheFile) {
  const fs::path video = encoded("libx264", ".mp4");
  const std::vector<uint8_t> bytes = read_file_bytes(video);
  const fs::path cut = fs::temp_directory_path() / "lfd_media_test_cut.mp4";
  std::ofstream(cut, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size() / 2));
  EXPECT_NE(open_error(cut).find(cut.string()), std::string::npos);
  const fs::path junk = fs::temp_directory_path() / "lfd_media_test_junk.mp4";
  std::ofstream(junk) << "not a video";
  EXPECT_NE(open_error(junk).find(junk.string()), std::string::npos);
  EXPECT_NE(open_error("/nonexistent/x.mp4").find("file not found"), std::string::npos);
}

TEST(YuvToRgb, KnownColoursOfBt709AndBt601) {
  auto convert = [](YuvMatrix m, YuvRange r, double y, double cb, double cr) {
    const YuvToRgb t = yuv_to_rgb_coefficients(m, r);
    const double v[3] = {y / 255 - t.offset[0], cb / 255 - t.offset[1], cr / 255 - t.offset[2]};
    std::array<double, 3> rgb{};
    for (int c = 0; c < 3; ++c) rgb[c] = t.matrix[c] * v[0] + t.matrix[3 + c] * v[1] + t.matrix[6 + c] * v[2];
    return rgb;
  };
  const auto white = convert(YuvMatrix::kBt709, YuvRange::kLimited, 235, 128, 128);
  const auto black = convert(YuvMatrix::kBt709, YuvRange::kLimited, 16, 128, 128);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(white[c], 1.0, 1e-6);
    EXPECT_NEAR(black[c], 0.0, 1e-6);
  }
  // Red in BT.709 limited range: Y 63, Cb 102, Cr 240 (rounded); in BT.601 full: Y 76, Cb 85, Cr 255.
  const auto red709 = convert(YuvMatrix::kBt709, YuvRange::kLimited, 62.97, 102.0, 240.0);
  const auto red601 = convert(YuvMatrix::kBt601, YuvRange::kFull, 76.245, 84.97, 255.5);
  for (const auto& red : {red709, red601}) {
    EXPECT_NEAR(red[0], 1.0, 0.01);
    EXPECT_NEAR(red[1], 0.0, 0.01);
    EXPECT_NEAR(red[2], 0.0, 0.01);
  }
}

}  // namespace
}  // namespace lfd::media
