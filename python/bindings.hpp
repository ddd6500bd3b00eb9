#pragma once
// The parts of the extension lfd._lfd (docs/python.md), each registering its classes and
// functions on the module; python/module.cpp calls them in order (a part may use the classes
// of the parts before it).
#include <pybind11/pybind11.h>

#include "lightfield/render_settings.hpp"

namespace lfd::python {

void bind_errors(pybind11::module_& m);     // python/errors.cpp
void bind_display(pybind11::module_& m);    // python/display_binding.cpp
void bind_scenes(pybind11::module_& m);     // python/scene_binding.cpp
void bind_quilt(pybind11::module_& m);      // python/quilt_binding.cpp
void bind_render(pybind11::module_& m);     // python/render_binding.cpp
void bind_window(pybind11::module_& m);     // python/window_binding.cpp

// `lfd render`'s settings of Python keyword arguments (None: not given); InputError naming an
// unknown keyword or a value of the wrong type (python/render_binding.cpp).
lightfield::RenderSettings settings_of(const pybind11::dict& keywords);

}  // namespace lfd::python
