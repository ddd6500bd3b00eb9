// lfd's errors as Python exceptions, with lfd's one-line messages: bad input (a file, a field, an
// argument) is lfd.InputError, a ValueError; no OpenGL 4.5 context is lfd.GlUnavailable, also
// an InputError (`lfd render --backend gl` exits 2 for it).
#include <pybind11/pybind11.h>

#include "gpu/gl/gl_context.hpp"
#include "python/bindings.hpp"
#include "util/error.hpp"

namespace lfd::python {

void bind_errors(pybind11::module_& m) {
  // Registered most derived last: pybind11 tries the translators newest first.
  static pybind11::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  static pybind11::exception<gpu::GlUnavailable> gl_unavailable(m, "GlUnavailable", input_error.ptr());
  pybind11::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const gpu::GlUnavailable& e) {
      gl_unavailable(e.what());
    } catch (const InputError& e) {
      input_error(e.what());
    }
  });
}

}  // namespace lfd::python
