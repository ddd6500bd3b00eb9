#pragma once
// `lfd bench direct --photos` (docs/performance.md "Direct panel rendering"): what an eye between
// two quilt views sees of each rendering path. For one display and scene: the direct panel and the
// quilt-path panel (nearest and linear view blending, the display's recommended view count) from
// the same sweeping planes, photographed through the optics simulator from eyes at fractions t
// between views j and j + 1, each photograph compared with the photograph of the per-view render at
// that exact eye's view position (validate/eye_photographs.hpp). The quilt path from exact per-view
// renders (nearest and linear) is photographed too: what view rounding costs without the planes'
// approximation. Prints a Markdown table row per eye; returns JSON.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lightfield/light_field_renderer.hpp"
#include "render/swizzle_blend.hpp"

namespace lfd::pipeline {

struct EyePhotoOptions {
  int chunks = 64;        // N_chunk of the planes
  int view_height = 512;  // view height; the width follows the display's aspect
  std::vector<int> views;  // j of each eye; empty: V/4, V/2 and 3V/4 of the display's V views
  std::vector<double> between = {0.0, 0.25, 0.5, 0.75};  // t of each eye (0: on view j's centre)
  int photo_width = 0;     // photograph width in pixels; 0: the view width
  int supersample = 3;     // simulator samples per photograph pixel per axis
  render::PlaneFilter direct_filter = render::PlaneFilter::kBilinear;

  // InputError "eye photographs: <field>: ..." for a value out of range.
  void check() const;
};

// `sweeping`: a G2LF renderer with the scene set. `scene_label` names the scene in the table.
nlohmann::ordered_json compare_eye_photographs(lightfield::LightFieldRenderer& sweeping,
                                               const scene::Scene& scene,
                                               const std::string& scene_label,
                                               const std::string& calibration_path,
                                               const EyePhotoOptions& options);

// The table's heading and column lines (printed once before the rows of every display).
void print_eye_photo_table_header(const EyePhotoOptions& options);

}  // namespace lfd::pipeline
