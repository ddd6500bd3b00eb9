#pragma once
// `lfd bench record` (docs/record.md "Speed"): frames per second of a recording, render + encode,
// against the same frames rendered and read back alone, in one run, so the encoder's share of
// the frame is known. Each run renders `frames` turntable frames both ways (alternating, so both
// sides see the same machine); the figures are medians over the runs after a warm-up run.
#include <filesystem>
#include <string>

#include <vector>

#include "lightfield/light_field_renderer.hpp"
#include "lightfield/view_plan.hpp"
#include "media/video_encoder.hpp"
#include "scene/scene.hpp"

namespace lfd::record {

struct RecordBenchOptions {
  int frames = 8;  // per run
  int runs = 3;    // timed runs, after one warm-up run
  media::EncoderOptions video;  // codec and quality
  std::filesystem::path work_dir = std::filesystem::temp_directory_path() / "lfd_bench_record";
};

struct RecordBenchRow {
  std::string device;    // the renderer's device() ("CPU, 2 OpenMP threads", the GL renderer string)
  int width = 0, height = 0;  // the quilt
  std::vector<double> render_fps;  // render + read-back + 8 bits, frames/s of each run
  std::vector<double> record_fps;  // the same + encoding, frames/s of each run
};

RecordBenchRow bench_record(lightfield::LightFieldRenderer& renderer, const scene::Scene& scene,
                            const lightfield::ViewRequest& request, const RecordBenchOptions& options);

}  // namespace lfd::record
