// lfd bench direct-photos: what eyes between two quilt views see of the direct panel and of the
// quilt path (pipeline/eye_photo_comparison.hpp).
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "apps/bench.hpp"
#include "apps/cli.hpp"
#include "bench/bench_renderers.hpp"
#include "pipeline/eye_photo_comparison.hpp"
#include "render/g2lf.hpp"
#include "render/scene_generator.hpp"
#include "scene/gaussian_io.hpp"
#include "util/atomic_file.hpp"
#include "util/data_dir.hpp"

namespace lfd::apps {

int RunBenchDirectPhotos(int argc, char** argv) {
  CLI::App app{
      "Photographs (the optics simulator of lfd simulate) of a display from distant eyes between two\n"
      "quilt views, at view fraction (j + 1/2 + t) / V: the direct panel and the quilt path (nearest and\n"
      "linear view blending, the display's recommended V) from the same sweeping planes, each against\n"
      "the photograph of the per-view render at that exact view position: PSNR per path per eye.\n"
      "\nExamples:\n"
      "  lfd bench direct-photos --calibration data/displays/go.visual.json --generated 20000\n"
      "  lfd bench direct-photos --scene ../shared/data/scenes/guitar.compressed.ply --generated 0 --json photos.json",
      "direct-photos"};
  pipeline::EyePhotoOptions o;
  std::string json_path, direct_filter = "bilinear";
  std::vector<std::string> scene_files;
  std::vector<size_t> generated = {100000};
  const std::filesystem::path displays = data_dir() / "displays";
  std::vector<std::string> calibrations = {(displays / "portrait.visual.json").string(),
                                           (displays / "16in-landscape-gen3.visual.json").string(),
                                           (displays / "go.visual.json").string()};
  app.add_option("--calibration", calibrations, "displays (visual.json or calibration.json), comma-separated")
      ->delimiter(',')->capture_default_str();
  app.add_option("--scene", scene_files, "scene files (repeatable; a missing one is skipped with a message)");
  app.add_option("--generated", generated, "Gaussians of generated tabletop scenes, comma-separated (0: none)")
      ->delimiter(',')->capture_default_str();
  app.add_option("--chunks", o.chunks, "N_chunk of the sweeping planes")->capture_default_str();
  app.add_option("--view-height", o.view_height, "view height in pixels (width: the display's aspect)")
      ->capture_default_str();
  app.add_option("--eye-views", o.views, "j of the eyes, comma-separated (default: V/4, V/2, 3V/4)")->delimiter(',');
  app.add_option("--eye-between", o.between, "t of the eyes in [0, 1), comma-separated (0: on view j's centre)")
      ->delimiter(',')->capture_default_str();
  app.add_option("--photo-width", o.photo_width, "photograph width in pixels (0: the view width)")
      ->capture_default_str();
  app.add_option("--supersample", o.supersample, "simulator samples per photograph pixel per axis")
      ->capture_default_str();
  app.add_option("--direct-filter", direct_filter, "the direct pass's plane sampling, nearest or bilinear")
      ->check(CLI::IsMember({"nearest", "bilinear"}))->capture_default_str();
  app.add_option("--json", json_path, "write the figures as JSON to this file");
  if (auto code = parse(app, argc, argv)) return *code;
  o.direct_filter = render::parse_plane_filter(direct_filter);
  o.check();
  std::setvbuf(stdout, nullptr, _IOLBF, 0);

  const bench::BenchRenderers renderers = bench::make_bench_renderers("cpu", scene::SceneKind::kGaussians);
  nlohmann::ordered_json out = {{"benchmark", "direct-photos"}, {"tables", nlohmann::ordered_json::array()}};
  pipeline::print_eye_photo_table_header(o);
  std::vector<std::pair<std::string, std::string>> scenes;  // label, file ("" generated)
  for (const std::string& f : scene_files) {
    if (std::filesystem::exists(f)) scenes.push_back({std::filesystem::path(f).filename().string(), f});
    else std::printf("(skipped %s: not found)\n", f.c_str());
  }
  for (size_t n : generated)
    if (n > 0) scenes.push_back({"generated " + std::to_string(n), ""});
  for (const auto& [label, file] : scenes) {
    scene::GaussianScene gaussians;
    if (!file.empty()) {
      gaussians = scene::load_gaussian_scene(file);
    } else {
      render::SceneGeneratorOptions g;
      g.count = std::stoul(label.substr(label.find(' ') + 1));
      gaussians = render::generate_scene(g);
    }
    const scene::Scene scene(std::move(gaussians));
    renderers.sweeping->set_scene(scene);
    for (const std::string& calibration : calibrations)
      out["tables"].push_back(pipeline::compare_eye_photographs(*renderers.sweeping, scene, label, calibration, o));
  }
  if (!json_path.empty()) {
    write_text_atomic(json_path, out.dump(2) + "\n");
    std::printf("\nwrote %s\n", json_path.c_str());
  }
  return 0;
}

}  // namespace lfd::apps
