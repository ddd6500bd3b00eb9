#include "python/render_call.hpp"

#include <map>
#include <mutex>
#include <thread>

#include "lightfield/backend_choice.hpp"
#include "lightfield/renderer_factory.hpp"
#include "util/error.hpp"

namespace lfd::python {
namespace {

constexpr auto kKeywords = lightfield::SettingNames::kKeywords;

std::mutex g_devices_mutex;
std::map<std::thread::id, std::shared_ptr<lightfield::GlDevice>> g_devices;

// The GL device of this thread (made on first use: a context is current on one thread), or null
// for the CPU; "auto" falls back to the CPU with a notice, as `lfd render --backend auto`.
std::shared_ptr<lightfield::GlDevice> device_for(const std::string& backend) {
  const lightfield::BackendChoice choice = lightfield::parse_backend_choice(backend, "backend");
  if (choice == lightfield::BackendChoice::kCpu) return nullptr;
  const std::lock_guard lock(g_devices_mutex);
  const std::thread::id thread = std::this_thread::get_id();
  if (const auto found = g_devices.find(thread); found != g_devices.end()) return found->second;
  auto device = lightfield::GlDevice::adopt(
      lightfield::open_backend_context(choice, lightfield::cpu_fallback_notice_on_stderr("backend")));
  if (device) g_devices[thread] = device;
  return device;
}

struct Prepared {
  std::unique_ptr<lightfield::LightFieldRenderer> renderer;
  lightfield::ViewPlan plan;
};

Prepared prepare(const RenderCall& call) {
  lightfield::check_render_settings(call.settings, kKeywords);
  lightfield::check_backend_settings(call.settings, call.backend == "cpu", kKeywords);
  const std::shared_ptr<lightfield::GlDevice> device = device_for(call.backend);
  const lightfield::RendererOptions options = lightfield::renderer_options(
      call.settings, call.scene->kind(), call.scene_name, lightfield::backend_for(device), kKeywords);
  Prepared p;
  p.plan = lightfield::plan_render_views(call.settings, call.display ? &*call.display : nullptr, *call.scene, kKeywords);
  p.renderer = lightfield::make_renderer(options, call.scene->kind(), device);
  p.renderer->set_scene(*call.scene);
  return p;
}

}  // namespace

PyQuilt render_quilt(const RenderCall& call) {
  Prepared p = prepare(call);
  p.renderer->render_quilt(p.plan.geometry, p.plan.layout);
  return PyQuilt{to_uint8(p.renderer->read_quilt()), p.plan.layout};
}

Image8 render_view(const RenderCall& call, int view) {
  Prepared p = prepare(call);
  if (view < 0 || view >= p.plan.views) throw_input_error("view: {} is outside 0..{}", view, p.plan.views - 1);
  return to_uint8(p.renderer->render_view(p.plan.geometry, view));
}

void use_gl_context() { device_for("gl"); }

void release_gl_devices() {
  const std::lock_guard lock(g_devices_mutex);
  g_devices.clear();
}

}  // namespace lfd::python
