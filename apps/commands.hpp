#pragma once
// One entry point per subcommand, COLMAP style: each parses its own options and calls
// library code. They throw lfd::InputError for bad input; main() maps errors to exit codes.

namespace lfd::apps {

int RunInfo(int argc, char** argv);
int RunInterlace(int argc, char** argv);
int RunSimulate(int argc, char** argv);
int RunValidate(int argc, char** argv);
int RunDemo(int argc, char** argv);
int RunRender(int argc, char** argv);
int RunView(int argc, char** argv);
int RunCompare(int argc, char** argv);
int RunScene(int argc, char** argv);
int RunBench(int argc, char** argv);
int RunPatterns(int argc, char** argv);
int RunCalibrate(int argc, char** argv);
int RunDevice(int argc, char** argv);
int RunBridge(int argc, char** argv);
int RunCamera(int argc, char** argv);
int RunPlay(int argc, char** argv);
int RunRgbdQuilt(int argc, char** argv);
int RunServe(int argc, char** argv);
int RunRecord(int argc, char** argv);

}  // namespace lfd::apps
