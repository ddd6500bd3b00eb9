#pragma once
// `lfd bench <name>`: one entry point per benchmark, dispatched from the table in bench.cpp.
// Each prints a table and, with --json FILE, writes its figures as JSON. To add one, declare
// it here and add a line to the table.

namespace lfd::apps {

int RunBenchRender(int argc, char** argv);  // apps/bench_render.cpp (also renderer-only)
int RunBenchVoxels(int argc, char** argv);  // apps/bench_voxels.cpp (also renderer-only)
int RunBenchGlVsCpu(int argc, char** argv);  // apps/bench_gl_vs_cpu.cpp (also renderer-only)
int RunBenchGpuFrame(int argc, char** argv);  // apps/bench_gpu_frame.cpp (also renderer-only)
int RunBenchGpuProbe(int argc, char** argv);  // apps/bench_gpu_probe.cpp (also renderer-only)
int RunBenchServe(int argc, char** argv);  // apps/bench_serve.cpp (also renderer-only)
int RunBenchDirect(int argc, char** argv);  // apps/bench_direct.cpp (also renderer-only)
int RunBenchSimulate(int argc, char** argv);  // apps/bench_simulate.cpp
int RunBenchCalibration(int argc, char** argv);  // apps/bench_calibration.cpp
int RunBenchCameraPoses(int argc, char** argv);  // apps/bench_camera_poses.cpp
int RunBenchDirectPhotos(int argc, char** argv);  // apps/bench_direct_photos.cpp
int RunBenchPlay(int argc, char** argv);  // apps/bench_play.cpp (also renderer-only)
int RunBenchRecord(int argc, char** argv);  // apps/bench_record.cpp (also renderer-only)
int RunBenchBridge(int argc, char** argv);  // apps/bench_bridge.cpp (also renderer-only)

}  // namespace lfd::apps
