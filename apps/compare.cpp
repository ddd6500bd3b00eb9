// `lfd compare`: PSNR and SSIM between two images of the same size.
//   lfd compare g2lf_qs5x9a1.png per-view_qs5x9a1.png [--json]
// SSIM: Gaussian 11x11 window, sigma 1.5, per RGB channel, averaged (render/image_metrics.hpp).
#include <cmath>
#include <iostream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "apps/cli.hpp"
#include "apps/commands.hpp"
#include "render/image_metrics.hpp"
#include "util/error.hpp"
#include "util/image.hpp"

namespace lfd::apps {

int RunCompare(int argc, char** argv) {
  CLI::App app{"Compare two images: PSNR (dB, peak 255) and SSIM (11x11 Gaussian, sigma 1.5,\n"
               "mean over RGB channels).\n"
               "Examples:\n"
               "  lfd compare g2lf_qs5x9a1.png per-view_qs5x9a1.png\n"
               "  lfd compare a.png b.png --json",
               "compare"};
  std::string a_path, b_path;
  bool json = false;
  app.add_option("A", a_path, "first image")->required();
  app.add_option("B", b_path, "second image")->required();
  app.add_flag("--json", json, "print machine-readable JSON");
  if (auto code = parse(app, argc, argv)) return *code;

  const ImageF a = to_float(read_image(a_path, 3)), b = to_float(read_image(b_path, 3));
  if (a.width != b.width || a.height != b.height)
    throw_input_error("{}: {}x{} differs from {}: {}x{}", a_path, a.width, a.height, b_path, b.width, b.height);
  const double p = render::psnr(a, b), s = render::ssim(a, b);
  if (json) {
    nlohmann::json j;
    j["a"] = a_path;
    j["b"] = b_path;
    j["identical"] = std::isinf(p);
    j["psnr_db"] = std::isinf(p) ? nlohmann::json(nullptr) : nlohmann::json(p);
    j["ssim"] = s;
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << fmt::format("PSNR {} dB\nSSIM {:.4f}\n", std::isinf(p) ? "inf" : fmt::format("{:.2f}", p), s);
  }
  return 0;
}

}  // namespace lfd::apps
