// `lfd scene`: make and inspect Gaussian scenes.
//   lfd scene generate --kind tabletop --count 30000 --seed 1 --sh-degree 1 --out demo.ply
//   lfd scene info scene.ply [--json]
//   lfd scene voxelize scene.ply --out scene.voxels [--level 8 | --max-voxels N] [--sh-degree D]
//   lfd scene convert scene.sog scene.spz      (reads every format load_scene knows; writes .ply, .spz)
#include <iostream>

#include <nlohmann/json.hpp>
#include <fmt/format.h>

#include "apps/cli.hpp"
#include "apps/commands.hpp"
#include "scene/scene_bounds.hpp"
#include "render/scene_generator.hpp"
#include "scene/gaussian_io.hpp"
#include "voxel/voxel_generator.hpp"
#include "scene/voxel_io.hpp"
#include "voxel/voxelize.hpp"

namespace lfd::apps {

namespace {

int generate(const render::SceneGeneratorOptions& options, const std::string& out) {
  const scene::GaussianScene scene = render::generate_scene(options);
  scene::save_ply(out, scene);
  std::cout << fmt::format("wrote {} ({} Gaussians, kind {}, seed {}, SH degree {})\n", out,
                           scene.size(), options.kind, options.seed, scene.sh_degree);
  return 0;
}

int generate_voxels(const voxel::VoxelGeneratorOptions& options, const std::string& out) {
  const scene::VoxelScene scene = voxel::generate_voxel_scene(options);
  scene::save_voxel_scene(out, scene);
  std::cout << fmt::format("wrote {} ({} voxels, levels up to {}, seed {}, SH degree {})\n", out, scene.size(),
                           options.detail_level, options.seed, scene.sh_degree);
  return 0;
}

int voxelize(const std::string& in, const voxel::VoxelizeOptions& options, const std::string& out) {
  const scene::GaussianScene gaussians = scene::load_gaussian_scene(in);
  voxel::VoxelizeReport report;
  const scene::VoxelScene scene = voxel::voxelize(gaussians, options, &report);
  scene::save_voxel_scene(out, scene);
  std::cout << fmt::format("wrote {} ({} voxels from {} Gaussians, levels up to {}, {} grid points, SH degree {}, "
                           "root {:.3f} units = inside cube * 2^{}; {} Gaussian centres outside it)\n",
                           out, scene.size(), gaussians.size(), report.finest_level, report.grid_points,
                           scene.sh_degree, scene.scene_extent, report.outside_levels, report.gaussians_outside);
  return 0;
}

int convert(const std::string& in, const std::string& out) {
  const scene::GaussianScene scene = scene::load_gaussian_scene(in);
  scene::save_gaussian_scene(out, scene);  // nothing is written when the input is bad (atomic)
  std::cout << fmt::format("wrote {} ({} Gaussians, SH degree {}) from {}\n", out, scene.size(),
                           scene.sh_degree, in);
  return 0;
}

int info(const std::string& path, bool json) {
  const scene::GaussianScene scene = scene::load_gaussian_scene(path);
  const scene::SceneBounds robust = scene::robust_bounds(scene);
  const scene::SceneBounds full = scene::exact_bounds(scene);
  if (json) {
    nlohmann::json j;
    j["file"] = path;
    j["gaussians"] = scene.size();
    j["sh_degree"] = scene.sh_degree;
    j["bounds_p01_p99"] = {{"min", robust.min}, {"max", robust.max}};
    j["bounds_all"] = {{"min", full.min}, {"max", full.max}};
    j["center"] = robust.center();
    j["radius"] = robust.radius();
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  auto vec = [](const std::array<float, 3>& v) {
    return fmt::format("({:.3f}, {:.3f}, {:.3f})", v[0], v[1], v[2]);
  };
  std::cout << fmt::format("file:       {}\n", path)
            << fmt::format("Gaussians:  {}\n", scene.size())
            << fmt::format("SH degree:  {} ({} coefficients per channel)\n", scene.sh_degree,
                           scene.sh_coeffs())
            << fmt::format("bounds 1-99%: {} .. {}\n", vec(robust.min), vec(robust.max))
            << fmt::format("bounds all:   {} .. {}\n", vec(full.min), vec(full.max))
            << fmt::format("center {}  radius {:.3f}\n", vec(robust.center()), robust.radius());
  return 0;
}

}  // namespace

int RunScene(int argc, char** argv) {
  CLI::App app{"Make and inspect 3D Gaussian Splatting scenes.\n"
               "Examples:\n"
               "  lfd scene generate --kind tabletop --count 30000 --seed 1 --out demo.ply\n"
               "  lfd scene generate --kind voxels --level 8 --out demo.voxels\n"
               "  lfd scene voxelize demo.ply --level 8 --out demo.voxels\n"
               "  lfd scene info data/scenes/demo.ply --json\n"
               "  lfd scene convert data/scenes/playbot.sog playbot.spz",
               "scene"};
  app.require_subcommand(1);

  render::SceneGeneratorOptions options;
  voxel::VoxelGeneratorOptions voxel_options;
  std::string out;
  std::vector<std::string> kinds = render::generator_kinds();
  kinds.push_back("voxels");  // sparse voxels (voxel/), written as a .voxels file
  CLI::App* gen = app.add_subcommand("generate", "write a procedural scene as a standard 3DGS PLY");
  gen->add_option("--kind", options.kind, "scene kind")
      ->check(CLI::IsMember(kinds))
      ->capture_default_str();
  gen->add_option("--count", options.count, "number of Gaussians")->capture_default_str();
  gen->add_option("--seed", options.seed, "random seed (same seed, same scene)")
      ->capture_default_str();
  gen->add_option("--sh-degree", options.sh_degree, "SH degree 0-3")->capture_default_str();
  gen->add_option("--level", voxel_options.detail_level,
                  "voxels: finest octree level near the objects (4-11; root 16 units)")->capture_default_str();
  gen->add_option("--out", out, "output .ply file (.voxels for --kind voxels)")->required();

  std::string path;
  bool json = false;
  CLI::App* inf = app.add_subcommand("info", "print counts, SH degree and bounds of a scene");
  inf->add_option("file", path, "scene file (.ply, compressed .ply, .splat, .spz)")
      ->required()
      ->check(CLI::ExistingFile);
  inf->add_flag("--json", json, "machine-readable output");

  voxel::VoxelizeOptions voxelize_options;
  std::string voxelize_in;
  CLI::App* vox = app.add_subcommand("voxelize", "turn a Gaussian scene into sparse voxels (.voxels)");
  vox->add_option("file", voxelize_in, "Gaussian scene (.ply, compressed .ply, .splat, .spz)")
      ->required()
      ->check(CLI::ExistingFile);
  vox->add_option("--level", voxelize_options.max_level,
                  "finest octree level within the inside cube (0.5-99.5% of the centres); outer levels add to it")
      ->capture_default_str();
  vox->add_option("--max-voxels", voxelize_options.max_voxels, "voxel budget, heaviest cells split first (0: none)")
      ->capture_default_str();
  vox->add_option("--sh-degree", voxelize_options.sh_degree, "SH degree 0-3 of the voxels (-1: the scene's)")
      ->capture_default_str();
  vox->add_option("--out", out, "output .voxels file")->required();

  std::string convert_in, convert_out;
  CLI::App* conv = app.add_subcommand(
      "convert", "convert a Gaussian scene: reads .ply, compressed .ply, .splat, .spz, .sog / meta.json, "
                 ".glb / .gltf, .ksplat; writes .ply or .spz (by the output's extension)");
  conv->add_option("in", convert_in, "input scene")->required()->check(CLI::ExistingFile);
  conv->add_option("out", convert_out, "output scene (.ply or .spz)")->required();

  if (auto code = parse(app, argc, argv)) return *code;
  if (conv->parsed()) return convert(convert_in, convert_out);
  if (vox->parsed()) return voxelize(voxelize_in, voxelize_options, out);
  if (gen->parsed() && options.kind == "voxels") {
    voxel_options.seed = options.seed;
    voxel_options.sh_degree = options.sh_degree;
    voxel_options.check();
    return generate_voxels(voxel_options, out);
  }
  if (gen->parsed()) {
    options.check();
    return generate(options, out);
  }
  return info(path, json);
}

}  // namespace lfd::apps
