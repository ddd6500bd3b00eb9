// lfd patterns: the calibration patterns for a display (docs/calibration.md section 1).
#include <cstdio>
#include <optional>
#include <string>

#include "apps/cli.hpp"
#include "apps/commands.hpp"
#include "display/calibration_file.hpp"
#include "device/drm_monitors.hpp"
#include "display/cover_layer.hpp"
#include "sim/patterns.hpp"
#include "util/error.hpp"

namespace lfd::apps {

namespace {

// A panel nobody described: the coarse set (board, white, black, fringes, lens probes).
int write_undescribed_patterns(int w, int h, double dpi, sim::PatternOptions options,
                               const sim::ProbeOptions& probes, const display::CoverLayer& cover,
                               const std::string& out_dir, bool force) {
  // Coarse sheets: the board's marker cells must span several lenses of 10 LPI.
  options.board_squares_short = std::min(options.board_squares_short, 4);
  sim::PatternSet set = sim::plan_undescribed_patterns(w, h, dpi, options, probes);
  // Nothing is known of a cover unless given: a bare sheet (the fine set keeps what is here).
  set.nominal.display.cover = cover;
  std::printf("cover layer: %.4g m at n = %.3g (%s)\n", cover.thickness_m, cover.refractive_index,
              cover.present() ? "given" : "none given: a bare sheet");
  sim::write_pattern_set(out_dir, set, force);
  std::printf("wrote %zu patterns (%dx%d: board, white, black, %d fringes, %zu lens probes of %d "
              "steps) and manifest.json to %s/patterns\n",
              set.patterns.size(), w, h, 2 * set.fringe_steps, set.probes.size(), set.probe_steps,
              out_dir.c_str());
  std::printf("next: photograph each full screen from one position (the screen filling 50-70 %% "
              "of the frame, head-on; manual exposure and focus, tripod) as "
              "%s/captures/pos1/<pattern file>, then run `lfd calibrate %s --out ...`\n",
              out_dir.c_str(), out_dir.c_str());
  return 0;
}

}  // namespace

int RunPatterns(int argc, char** argv) {
  CLI::App app{
      "Write the calibration patterns for a display: DIR/patterns/*.png at panel resolution\n"
      "and DIR/patterns/manifest.json. Show each full screen on the display, photograph it\n"
      "from 2-3 camera positions and save the photos as DIR/captures/<position>/<file>, then\n"
      "run `lfd calibrate DIR`.\n"
      "\nExamples:\n"
      "  lfd patterns --display data/displays/16in-gen2.visual.json --out unit42\n"
      "  lfd patterns --display visual.json --out unit42 --steps 12 --force\n"
      "  lfd patterns --device auto --out unit42   (the attached unit's factory calibration)\n"
      "  lfd patterns --screen 1920x1200 --dpi 224 --out tablet   (a panel nobody described:\n"
      "      the lens probes; `lfd calibrate tablet` then draws the fine set for the lens found)",
      "patterns"};
  std::string out_dir;
  DisplaySource display_source;
  sim::PatternOptions options;
  bool force = false;
  display_source.add(app, "--display",
                     "nominal display: visual.json (template or factory) or calibration.json",
                     false);
  std::string screen;
  std::optional<double> dpi;
  sim::ProbeOptions probes;
  app.add_option("--screen", screen,
                 "a panel nobody described: its resolution WxH (with --dpi; instead of "
                 "--display): the lens probes, no lens description needed");
  std::optional<std::string> monitor;
  app.add_option("--monitor", monitor,
                 "a panel nobody described, attached: the connected monitor whose EDID name "
                 "starts with this (\"\" for the only one) gives the resolution and, from its "
                 "physical size, the DPI (instead of --screen and --dpi)");
  app.add_option("--dpi", dpi, "the undescribed panel's pixels per inch (diagonal px / inches)")
      ->check(CLI::Range(20.0, 2000.0));
  app.add_option("--min-lpi", probes.min_lpi,
                 "undescribed: smallest lens pitch to look for, lenticules per inch")
      ->capture_default_str()
      ->check(CLI::Range(1.0, 500.0));
  app.add_option("--max-lpi", probes.max_lpi, "undescribed: largest lens pitch to look for")
      ->capture_default_str()
      ->check(CLI::Range(2.0, 1000.0));
  app.add_option("--max-slant", probes.max_slant_deg,
                 "undescribed: largest lens slant from vertical to look for, degrees, either way")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 60.0));
  app.add_option("--camera-px", probes.camera_px_across,
                 "undescribed: camera pixels the screen will span in the photos (its width)")
      ->capture_default_str()
      ->check(CLI::Range(100.0, 20000.0));
  app.add_option("--out", out_dir, "output folder (patterns go to OUT/patterns)")->required();
  app.add_option("--steps", options.phase_steps, "phase-shift steps K")
      ->capture_default_str()
      ->check(CLI::Range(3, 32));
  app.add_option("--board-squares", options.board_squares_short,
                 "ChArUco squares along the short side of the panel")
      ->capture_default_str()
      ->check(CLI::Range(3, 20));
  std::optional<double> cover_thickness_m, cover_index;
  app.add_option("--cover-thickness", cover_thickness_m,
                 "acrylic block / cover glass in front of the lenses, metres (default: the "
                 "display's calibration.json, else its family's; 0: a bare panel)")
      ->check(CLI::Range(0.0, 0.2));
  app.add_option("--cover-index", cover_index, "the cover's refractive index")
      ->check(CLI::Range(1.0, 3.0));
  app.add_flag("--force", force, "replace existing patterns");
  if (auto code = parse(app, argc, argv)) return *code;
  display::CoverLayer given_cover;
  if (cover_thickness_m) given_cover.thickness_m = *cover_thickness_m;
  if (cover_index) given_cover.refractive_index = *cover_index;
  if (monitor) {
    const device::MonitorPanel panel =
        device::monitor_panel(device::connected_monitors("/"), *monitor);
    std::printf("monitor %s: %.1f dpi\n", panel.monitor.c_str(), panel.dpi);
    return write_undescribed_patterns(panel.width_px, panel.height_px, panel.dpi, options, probes,
                                      given_cover, out_dir, force);
  }
  if (!screen.empty()) {
    int w = 0, h = 0;
    char tail = 0;
    if (std::sscanf(screen.c_str(), "%dx%d%c", &w, &h, &tail) != 2 || w < 64 || h < 64 ||
        w > 20000 || h > 20000)
      throw_input_error("--screen {}: must be WxH in pixels, e.g. 1920x1200", screen);
    if (!dpi) throw_input_error("--screen needs --dpi (the panel's pixels per inch)");
    return write_undescribed_patterns(w, h, *dpi, options, probes, given_cover, out_dir, force);
  }
  if (!display_source.given())
    throw_input_error("--display, --device, --screen WxH --dpi D or --monitor NAME is required");

  display::Calibration nominal = display_source.load();
  // visual.json cannot say what covers the lenses: the family's block unless told.
  auto& cover = nominal.display.cover;
  std::string cover_source = "the display file";
  if (!cover.present() && !cover_thickness_m) {
    const display::CoverDefault family = display::cover_layer_for_family(nominal.display);
    cover = family.cover;
    cover_source = "default of the family " + family.family;
  }
  if (cover_thickness_m) cover.thickness_m = *cover_thickness_m;
  if (cover_index) cover.refractive_index = *cover_index;
  if (cover_thickness_m || cover_index) cover_source = "given";
  std::printf("cover layer: %.4g m at n = %.3g (%s)\n", cover.thickness_m,
              cover.refractive_index, cover_source.c_str());
  const sim::PatternSet set = sim::plan_patterns(nominal, options);
  sim::write_pattern_set(out_dir, set, force);
  std::printf("wrote %zu patterns (%dx%d) and manifest.json to %s/patterns\n", set.patterns.size(),
              nominal.display.screen_w, nominal.display.screen_h, out_dir.c_str());
  std::printf("next: photograph each pattern full screen (manual exposure and focus, tripod) and "
              "save as %s/captures/<position>/<pattern file>\n",
              out_dir.c_str());
  return 0;
}

}  // namespace lfd::apps
