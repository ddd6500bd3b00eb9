#include "lightfield/light_field_renderer.hpp"

#include "util/error.hpp"

namespace lfd::lightfield {

QuiltStats LightFieldRenderer::render_panel(const render::QuiltGeometry&, const display::LensModel&,
                                            const PanelOptions&) {
  throw_input_error("direct panel: this {} renderer has no direct pass (the sweeping planes have one: g2lf, v2lf)",
                    name());
}

const ImageF& LightFieldRenderer::read_panel() {
  throw_input_error("direct panel: the {} renderer's method renders no panel", name());
}

}  // namespace lfd::lightfield
