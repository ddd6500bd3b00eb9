#pragma once
// What the `lfd record` tests share: small recordings of the bundled demo scene, the video decoded
// back with FFmpeg (media::VideoDecoder), and `lfd render --camera` of a saved camera to compare.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "media/video_decoder.hpp"
#include "tests/support/run_lfd.hpp"
#include "tests/test_data.hpp"
#include "util/image.hpp"

namespace lfd::test {

inline const std::string kRecordScene = (project_data() / "scenes" / "demo.ply").string();
// Tiny quilts: 4 views of 48x32 in 2x2 tiles, 8 depth chunks.
inline const std::string kRecordSmall = " --views 4 --cols 2 --rows 2 --size 48x32 --chunks 8 ";

struct DecodedVideo {
  media::VideoInfo info;
  std::vector<Image8> frames;  // RGB (media::yuv_to_rgb)
  std::vector<Image8> luma;    // the Y planes as decoded (one channel)
};

// BT.709 luma in limited range, as the encoder tags it (ITU-R BT.709: Y' = 0.2126 R' + 0.7152 G'
// + 0.0722 B', scaled to 16..235): the reference a decoded Y plane is compared with, so the
// comparison measures the codec's loss and not 4:2:0's halved colour resolution.
inline Image8 bt709_luma(const Image8& rgb) {
  Image8 y(rgb.width, rgb.height, 1);
  for (size_t i = 0; i < size_t(rgb.width) * rgb.height; ++i) {
    const double l = 0.2126 * rgb.pixels[3 * i] + 0.7152 * rgb.pixels[3 * i + 1] + 0.0722 * rgb.pixels[3 * i + 2];
    y.pixels[i] = uint8_t(std::lround(16.0 + l * 219.0 / 255.0));
  }
  return y;
}

inline DecodedVideo decode_video(const std::filesystem::path& path) {
  media::DecoderOptions o;
  o.try_hardware = false;
  media::VideoDecoder decoder(path, o);
  DecodedVideo v;
  v.info = decoder.info();
  while (auto frame = decoder.next_frame()) {
    v.frames.push_back(media::yuv_to_rgb(*frame));
    const media::YuvPlane& y = frame->planes[0];
    Image8 luma(y.width, y.height, 1);
    for (int row = 0; row < y.height; ++row)
      std::copy(y.data + size_t(row) * y.stride, y.data + size_t(row) * y.stride + y.width, luma.row(row));
    v.luma.push_back(luma);
  }
  return v;
}

// The files in `dir` whose names end in `suffix`.
inline std::vector<std::filesystem::path> files_ending(const std::filesystem::path& dir, const std::string& suffix) {
  std::vector<std::filesystem::path> found;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().filename().string().ends_with(suffix)) found.push_back(e.path());
  return found;
}

// `lfd render --camera CAM` with the recording's options: the quilt it writes.
inline Image8 render_saved_camera(const std::filesystem::path& camera, const std::filesystem::path& dir,
                                  const std::string& options = kRecordSmall) {
  const std::filesystem::path out = dir / (camera.stem().string() + "_render.png");
  const RunResult r = run_lfd("render --scene " + kRecordScene + " --camera " + camera.string() + options +
                              " --out " + out.string());
  if (r.exit_code != 0) throw std::runtime_error(r.output);
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().filename().string().starts_with(camera.stem().string() + "_render_qs"))
      return read_image(e.path(), 3);
  throw std::runtime_error("no quilt written for " + camera.string());
}

}  // namespace lfd::test
