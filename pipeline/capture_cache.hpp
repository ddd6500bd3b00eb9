#pragma once
// Simulated calibration photos kept on disk between benchmark runs: simulating is most of a
// calibration benchmark's time, and the same settings give the same photos.
#include <filesystem>
#include <string>
#include <vector>

#include "sim/capture_io.hpp"
#include "display/calibration_file.hpp"
#include "sim/patterns.hpp"
#include "sim/synthetic_unit.hpp"

namespace lfd::pipeline {

// The captures of `key` (a name that encodes every setting that changes them) from
// `cache_dir` if an earlier run left them complete there; else simulated and, with a cache,
// saved as 16-bit PNGs in a capture folder (DIR/captures/<position>/<stem>.png). An empty
// `cache_dir` only simulates.
std::vector<sim::PositionCaptures> cached_captures(const std::filesystem::path& cache_dir,
                                                     const std::string& key,
                                                     const sim::PatternSet& set,
                                                     const display::Calibration& truth,
                                                     const sim::CaptureRig& rig);

}  // namespace lfd::pipeline
