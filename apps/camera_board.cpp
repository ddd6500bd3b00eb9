// lfd camera board: the ChArUco board that `lfd camera calibrate` looks for, as a PNG.
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "apps/camera.hpp"
#include "apps/cli.hpp"
#include "util/error.hpp"
#include "util/image.hpp"

namespace lfd::apps {

int RunCameraBoard(int argc, char** argv) {
  CLI::App app{
      "Write the ChArUco board for the camera's calibration as a PNG. Print it at 100 % scale\n"
      "(no 'fit to page') on stiff, flat paper, or show it full screen on a monitor with\n"
      "--square-px; then photograph it with `lfd camera calibrate`'s guide (docs/calibration.md).\n"
      "\nExamples:\n"
      "  lfd camera board --out board.png                  (9x6 squares of 30 mm at 300 DPI: A4)\n"
      "  lfd camera board --out board.png --squares 12x8 --square-mm 20\n"
      "  lfd camera board --out screen.png --square-px 200  (to show on a 1920x1080 monitor)",
      "board"};
  std::string out_path;
  CameraBoardFlags board_flags;
  double dpi = 300, margin_mm = 10;
  int square_px = 0;
  bool force = false;
  app.add_option("--out", out_path, "PNG to write")->required();
  board_flags.add(app);
  app.add_option("--dpi", dpi, "printer resolution: pixels per inch of the PNG")
      ->capture_default_str()
      ->check(CLI::Range(50.0, 2400.0));
  app.add_option("--square-px", square_px,
                 "pixels per square instead of --square-mm at --dpi (for a screen)")
      ->check(CLI::Range(20, 2000));
  app.add_option("--margin-mm", margin_mm, "white margin around the board")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 200.0));
  app.add_flag("--force", force, "replace an existing file");
  if (auto code = parse(app, argc, argv)) return *code;

  const calib::CameraBoardSpec board = board_flags.parse();
  if (std::filesystem::exists(out_path) && !force)
    throw_input_error("{}: exists; pass --force to replace it", out_path);
  const double px_per_mm = dpi / 25.4;
  const bool for_print = square_px == 0;
  if (for_print) square_px = int(std::lround(board.square_mm * px_per_mm));
  const int margin_px = int(std::lround(for_print ? margin_mm * px_per_mm
                                                  : margin_mm / board.square_mm * square_px));
  const cv::Mat img = calib::render_camera_board(board, square_px, margin_px);
  Image8 png(img.cols, img.rows, 1);
  for (int y = 0; y < img.rows; ++y)
    std::copy_n(img.ptr<uint8_t>(y), img.cols, png.row(y));
  write_png(out_path, png);
  std::printf("wrote %s: %dx%d squares, %d x %d px\n", out_path.c_str(), board.squares_x,
              board.squares_y, img.cols, img.rows);
  if (for_print)
    std::printf("print at %.0f DPI, 100 %% scale: squares of %.1f mm, the board %.0f x %.0f mm; "
                "measure a square after printing and pass it as --square-mm\n",
                dpi, square_px / px_per_mm, board.squares_x * square_px / px_per_mm,
                board.squares_y * square_px / px_per_mm);
  else
    std::printf("show it full screen at 1:1 pixels; give --square-mm as the square measured on "
                "the screen\n");
  return 0;
}

}  // namespace lfd::apps
