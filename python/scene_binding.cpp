#include "python/scene_binding.hpp"

#include <cmath>
#include <cstring>

#include <pybind11/numpy.h>
#include <pybind11/stl/filesystem.h>

#include "python/arrays.hpp"
#include "python/bindings.hpp"
#include "scene/scene_checks.hpp"
#include "util/error.hpp"

namespace py = pybind11;

namespace lfd::python {
namespace {

struct PyGaussians : PyScene {};
struct PyVoxels : PyScene {};

// A per-Gaussian opacity array: (N,) as gsplat keeps it, or (N, 1) as the 3DGS PLY's trainer.
FloatArray opacity_array(const py::handle& value, const std::string& name, AxisLengths& lengths) {
  const py::array any = py::array::ensure(as_numpy(value));
  if (any && any.ndim() == 2) return checked_float_array(value, name, {{-1, "N"}, {1}}, lengths);
  return checked_float_array(value, name, {{-1, "N"}}, lengths);
}

// The scene of the arrays, in the 3DGS PLY's stored convention (log scales, opacity logits) or,
// `activated`, as gsplat hands them to its rasterizer (scales, opacities); docs/python.md.
scene::GaussianScene gaussians_of_arrays(const py::kwargs& kw) {
  const auto arg = [&kw](const char* name) { return kw.contains(name) ? py::handle(kw[name]) : py::handle(py::none()); };
  const bool activated = kw.contains("activated") && kw["activated"].cast<bool>();
  for (const auto& item : kw) {
    const std::string key = py::str(item.first);
    static const char* kKnown[] = {"means", "rotations", "sh", "log_scales", "opacity_logits", "scales", "opacities",
                                   "activated"};
    if (std::find_if(std::begin(kKnown), std::end(kKnown), [&](const char* k) { return key == k; }) == std::end(kKnown))
      throw_input_error("{}: not an argument of lfd.Gaussians (means, rotations, sh, log_scales, opacity_logits; "
                        "scales, opacities with activated=True)", key);
  }
  const char* scales_name = activated ? "scales" : "log_scales";
  const char* opacity_name = activated ? "opacities" : "opacity_logits";
  const char* other_scales = activated ? "log_scales" : "scales";
  const char* other_opacity = activated ? "opacity_logits" : "opacities";
  for (const char* wrong : {other_scales, other_opacity})
    if (!arg(wrong).is_none())
      throw_input_error("{}: given with activated={}; that takes {} and {}", wrong, activated ? "True" : "False",
                        scales_name, opacity_name);

  AxisLengths lengths;
  const FloatArray means = checked_float_array(arg("means"), "means", {{-1, "N"}, {3}}, lengths);
  const FloatArray scales = checked_float_array(arg(scales_name), scales_name, {{-1, "N"}, {3}}, lengths);
  const FloatArray rotations = checked_float_array(arg("rotations"), "rotations", {{-1, "N"}, {4}}, lengths);
  if (arg(opacity_name).is_none()) throw_input_error("{}: required, an array of shape (N,)", opacity_name);
  const FloatArray opacities = opacity_array(arg(opacity_name), opacity_name, lengths);
  const FloatArray sh = checked_float_array(arg("sh"), "sh", {{-1, "N"}, {-1, "K"}, {3}}, lengths);
  const long coeffs = long(sh.shape(1));
  const int degree = int(std::lround(std::sqrt(double(coeffs)))) - 1;
  if (degree < 0 || degree > 3 || (degree + 1) * (degree + 1) != coeffs)
    throw_input_error("sh: {} coefficients per colour; expected 1, 4, 9 or 16 (SH degree 0-3, the DC first)", coeffs);

  scene::GaussianScene g;
  const size_t n = size_t(means.shape(0));
  scene::resize_scene(g, n, degree);
  std::memcpy(g.positions.data(), means.data(), n * 3 * sizeof(float));
  std::memcpy(g.rotations.data(), rotations.data(), n * 4 * sizeof(float));
  std::memcpy(g.sh.data(), sh.data(), g.sh.size() * sizeof(float));
  const float* s = scales.data();
  const float* o = opacities.data();
  for (size_t i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) g.scales[i][k] = activated ? s[i * 3 + k] : std::exp(s[i * 3 + k]);
    g.opacities[i] = activated ? o[i] : scene::sigmoid(o[i]);
  }
  if (activated)
    for (size_t i = 0; i < n; ++i)
      if (!(g.opacities[i] >= 0.0f && g.opacities[i] <= 1.0f))
        throw_input_error("opacities: [{}] = {} is outside [0, 1] (opacity_logits without activated=True?)", i,
                          g.opacities[i]);
  scene::finalize_scene(g, "Gaussians");
  return g;
}

// A read-only numpy view of `count` x `row` floats at `data`, kept alive by `owner`.
py::array float_view(const float* data, std::vector<py::ssize_t> shape, const py::handle& owner) {
  std::vector<py::ssize_t> strides(shape.size());
  py::ssize_t stride = sizeof(float);
  for (size_t k = shape.size(); k-- > 0;) {
    strides[k] = stride;
    stride *= shape[k];
  }
  py::array view(py::dtype::of<float>(), shape, strides, data, owner);
  py::detail::array_proxy(view.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return view;
}

const scene::GaussianScene& gaussians_of(const PyScene& s) { return s.scene->gaussians(); }

// A scene file that must hold `kind` (the class asked for); InputError naming the other class.
PyScene load_kind(const std::filesystem::path& path, scene::SceneKind kind) {
  if (scene::scene_kind_of_file(path) != kind)
    throw_input_error("{}: holds {}; read it with lfd.{}.load", path.string(),
                      kind == scene::SceneKind::kGaussians ? "sparse voxels" : "Gaussians",
                      kind == scene::SceneKind::kGaussians ? "Voxels" : "Gaussians");
  return PyScene{std::make_shared<const scene::Scene>(scene::load_scene(path)), path.string()};
}

}  // namespace

void bind_scenes(py::module_& m) {
  py::class_<PyScene>(m, "Scene", "A scene lfd renders: lfd.Gaussians or lfd.Voxels.")
      .def_property_readonly("kind", [](const PyScene& s) {
        return s.scene->kind() == scene::SceneKind::kGaussians ? "gaussians" : "voxels";
      })
      .def_property_readonly("name", [](const PyScene& s) { return s.name; })
      .def("__len__", [](const PyScene& s) { return s.scene->size(); })
      .def("__repr__", [](const PyScene& s) {
        return "<lfd." + std::string(s.scene->kind() == scene::SceneKind::kGaussians ? "Gaussians " : "Voxels ") +
               s.name + ": " + std::to_string(s.scene->size()) + " " + s.scene->primitives() + ">";
      });
  m.def(
      "load",
      [](const std::filesystem::path& path) -> py::object {
        auto scene = std::make_shared<const scene::Scene>(scene::load_scene(path));
        if (scene->kind() == scene::SceneKind::kGaussians) return py::cast(PyGaussians{{scene, path.string()}});
        return py::cast(PyVoxels{{scene, path.string()}});
      },
      py::arg("path"), "Reads a scene file of either kind (every format `lfd render --scene` reads).");

  py::class_<PyGaussians, PyScene>(m, "Gaussians", "3D Gaussians (3DGS).")
      .def(py::init([](const py::kwargs& kw) {
             auto scene = std::make_shared<const scene::Scene>(gaussians_of_arrays(kw));
             return PyGaussians{{scene, "the Gaussians"}};
           }),
           "Gaussians(means=, log_scales=, rotations=, opacity_logits=, sh=) in the 3DGS PLY's convention, or "
           "Gaussians(means=, scales=, rotations=, opacities=, sh=, activated=True) as gsplat rasterizes them; "
           "rotations (w, x, y, z), sh N x K x 3 with the DC first.")
      .def_static(
          "load",
          [](const std::filesystem::path& path) { return PyGaussians{load_kind(path, scene::SceneKind::kGaussians)}; },
          py::arg("path"), "PLY, compressed PLY, .splat, SPZ, SOG, glTF/GLB, .ksplat.")
      .def_property_readonly("sh_degree", [](const PyScene& s) { return gaussians_of(s).sh_degree; })
      .def_property_readonly("means", [](py::object self) {
        const auto& g = gaussians_of(self.cast<const PyScene&>());
        return float_view(reinterpret_cast<const float*>(g.positions.data()), {py::ssize_t(g.size()), 3}, self);
      }, "N x 3, read-only")
      .def_property_readonly("scales", [](py::object self) {
        const auto& g = gaussians_of(self.cast<const PyScene&>());
        return float_view(reinterpret_cast<const float*>(g.scales.data()), {py::ssize_t(g.size()), 3}, self);
      }, "N x 3 linear scales (activated), read-only")
      .def_property_readonly("rotations", [](py::object self) {
        const auto& g = gaussians_of(self.cast<const PyScene&>());
        return float_view(reinterpret_cast<const float*>(g.rotations.data()), {py::ssize_t(g.size()), 4}, self);
      }, "N x 4 unit quaternions (w, x, y, z), read-only")
      .def_property_readonly("opacities", [](py::object self) {
        const auto& g = gaussians_of(self.cast<const PyScene&>());
        return float_view(g.opacities.data(), {py::ssize_t(g.size())}, self);
      }, "N opacities in [0, 1] (activated), read-only")
      .def_property_readonly("sh", [](py::object self) {
        const auto& g = gaussians_of(self.cast<const PyScene&>());
        return float_view(g.sh.data(), {py::ssize_t(g.size()), g.sh_coeffs(), 3}, self);
      }, "N x K x 3 SH coefficients, the DC first, read-only");

  py::class_<PyVoxels, PyScene>(m, "Voxels", "A sparse-voxel radiance field (SVRaster's representation).")
      .def_static(
          "load",
          [](const std::filesystem::path& path) { return PyVoxels{load_kind(path, scene::SceneKind::kVoxels)}; },
          py::arg("path"), ".voxels or the svraster-webgl PLY.")
      .def_property_readonly("sh_degree", [](const PyScene& s) { return s.scene->voxels().sh_degree; });
}

}  // namespace lfd::python
