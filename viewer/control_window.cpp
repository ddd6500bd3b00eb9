#include "viewer/control_window.hpp"

#include <algorithm>
#include <cstdint>

#include <epoxy/gl.h>
#include <GLFW/glfw3.h>
#include <fmt/format.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include "gpu/gl/gl_context.hpp"

namespace lfd::viewer {
namespace {

// ImGui::Image of a texture scaled to `width`, flipped to show GL's bottom-up rows upright.
void show_texture(const gpu::Texture& t, float width) {
  const float height = width * float(t.height()) / float(t.width());
  ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(t.id())), ImVec2(width, height),
               ImVec2(0, 1), ImVec2(1, 0));
}

double ms(double seconds) { return seconds * 1e3; }

// ImGui 1.86 (Debian 12) has no SeparatorText.
void section(const char* title) {
  ImGui::Separator();
  ImGui::TextUnformatted(title);
}

}  // namespace

ControlWindow::ControlWindow(const gpu::GlfwSession&, GLFWwindow* share) {
  glfwDefaultWindowHints();
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  window_ = glfwCreateWindow(520, 900, "lfd view: controls", nullptr, share);
  if (!window_)
    throw gpu::GlUnavailable(fmt::format("no GL: no control window ({})", gpu::GlfwSession::last_error()));
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(0);  // the display window paces the loop
  IMGUI_CHECKVERSION();
  ImGuiContext* context = ImGui::CreateContext();
  imgui_context_ = context;
  ImGui::GetIO().IniFilename = nullptr;  // the viewer's own config file holds what matters
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
  ImGui_ImplOpenGL3_Init("#version 410");
  glfwMakeContextCurrent(share);
}

ControlWindow::~ControlWindow() {
  if (!window_) return;
  // The display window's objects are destroyed after this: give its context back.
  GLFWwindow* previous = glfwGetCurrentContext();
  glfwMakeContextCurrent(window_);
  ImGui::SetCurrentContext(static_cast<ImGuiContext*>(imgui_context_));
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext(static_cast<ImGuiContext*>(imgui_context_));
  glfwDestroyWindow(window_);
  glfwMakeContextCurrent(previous != window_ ? previous : nullptr);
}

void ControlWindow::place_beside(GLFWwindow* other) {
  int x = 0, y = 0, width = 0, height = 0;
  glfwGetWindowPos(other, &x, &y);
  glfwGetWindowSize(other, &width, &height);
  glfwSetWindowPos(window_, x + width + 8, y);
}

bool ControlWindow::should_close() const { return glfwWindowShouldClose(window_); }

bool ControlWindow::wants_mouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool ControlWindow::wants_keyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

void ControlWindow::begin_frame() {
  glfwMakeContextCurrent(window_);
  ImGui::SetCurrentContext(static_cast<ImGuiContext*>(imgui_context_));
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(ImVec2(float(w), float(h)));
  ImGui::Begin("lfd view", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove);
}

void ControlWindow::end_frame(GLFWwindow* restore) {
  ImGui::End();
  ImGui::Render();
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  glViewport(0, 0, w, h);
  glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  glfwSwapBuffers(window_);
  glfwMakeContextCurrent(restore);
}

void ControlWindow::draw_progress(const std::string& what, double fraction, GLFWwindow* restore) {
  begin_frame();
  ImGui::TextUnformatted(what.c_str());
  ImGui::ProgressBar(float(std::clamp(fraction, 0.0, 1.0)), ImVec2(-1.0f, 0.0f));
  end_frame(restore);
}

ControlActions ControlWindow::draw(ViewerSettings& s, SeenFromControls& seen, const FrameReport& r,
                                   const ControlImages& images, GLFWwindow* restore) {
  ControlActions actions;
  begin_frame();

  ImGui::TextUnformatted(r.display.c_str());
  ImGui::TextUnformatted(r.renderer.c_str());
  ImGui::Text("%.1f FPS  (%.2f ms a frame, p99 %.2f ms)", r.frame_seconds > 0 ? 1.0 / r.frame_seconds : 0.0,
              ms(r.frame_seconds), ms(r.frame_p99_seconds));
  if (s.method != Method::kPerView)
    ImGui::Text("GPU: binning+sort %.2f  planes %.2f  swizzle %.2f  interlace %.2f ms", ms(r.binning_seconds),
                ms(r.planes_seconds), ms(r.swizzle_seconds), ms(r.interlace_seconds));
  else
    ImGui::Text("GPU: per-view raster %.2f  interlace %.2f ms", ms(r.raster_seconds), ms(r.interlace_seconds));
  ImGui::Text("%d views (%dx%d of %dx%d), cone %.1f deg; planes %.1f MiB, GPU peak %.1f MiB", r.views,
              r.cols, r.rows, r.view_width, r.view_height, r.view_cone_deg, r.plane_bytes / 1048576.0,
              r.gpu_peak_bytes / 1048576.0);
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.8f, 0.3f, 1.0f));
  for (const std::string& notice : r.fit_notices) ImGui::TextWrapped("fit: %s", notice.c_str());
  ImGui::PopStyleColor();

  section("Method");
  int method = s.method == Method::kG2lf ? 0 : s.method == Method::kPerView ? 1 : 2;
  ImGui::RadioButton("G2LF", &method, 0);
  ImGui::SameLine();
  ImGui::RadioButton("per view", &method, 1);
  ImGui::SameLine();
  ImGui::RadioButton("G2LF direct", &method, 2);  // no quilt: swizzle = the direct pass, interlace 0
  s.method = method == 0 ? Method::kG2lf : method == 1 ? Method::kPerView : Method::kG2lfDirect;
  if (s.method != Method::kPerView) {
    ImGui::SliderInt("N_chunk", &s.g2lf.chunks, 1, 1024, "%d", ImGuiSliderFlags_Logarithmic);
    ImGui::SliderInt("P_s", &s.g2lf.plane_scale, 1, 4);
    int filter = s.g2lf.filter == render::PlaneFilter::kBilinear;
    ImGui::Combo("filter", &filter, "nearest\0bilinear\0");
    s.g2lf.filter = filter ? render::PlaneFilter::kBilinear : render::PlaneFilter::kNearest;
    int binning = s.g2lf.binning == render::ChunkBinning::kQuantile;
    ImGui::Combo("binning", &binning, "mixed\0quantile\0");
    s.g2lf.binning = binning ? render::ChunkBinning::kQuantile : render::ChunkBinning::kMixed;
    int precision = s.g2lf.precision == render::PlanePrecision::kF32;
    ImGui::Combo("planes", &precision, "RGBA8\0RGBA32F\0");
    s.g2lf.precision = precision ? render::PlanePrecision::kF32 : render::PlanePrecision::kU8;
  }
  section("Light field");
  ImGui::SliderInt("views", &s.views, 0, 100, s.views == 0 ? "display's" : "%d");
  ImGui::SliderFloat("view cone", &s.view_cone_deg, 0.0f, 80.0f, s.view_cone_deg == 0 ? "display's" : "%.1f deg");
  ImGui::SliderFloat("focal distance", &s.focal_fraction, 0.2f, 5.0f, "%.2f x target", ImGuiSliderFlags_Logarithmic);
  ImGui::SliderFloat("depthiness", &s.depthiness, 0.05f, 3.0f, "%.2f");
  ImGui::SliderInt("view height", &s.view_height_px, 64, 1024);
  ImGui::ColorEdit3("background", &s.background.r);

  section("Camera");
  ImGui::TextUnformatted("drag: orbit, right drag / shift: pan, wheel: zoom, arrows/WASD, R: reset");
  if (ImGui::Button("reset camera")) actions.reset_camera = true;
  ImGui::SameLine();
  if (ImGui::Button("screenshot")) actions.screenshot = true;
  ImGui::SameLine();
  if (ImGui::Button("save quilt")) actions.save_quilt = true;
  ImGui::SameLine();
  if (ImGui::Button("save cam.json")) actions.save_camera = true;
  if (ImGui::Button("remember these settings for this display")) actions.save_settings = true;

  section("Seen from");
  ImGui::Checkbox("what an eye here sees (lfd simulate's optics)", &seen.visible);
  if (seen.visible) {
    const float reach = float(std::max(r.view_cone_deg, 10.0));  // a little past the cone's edges
    float angle = float(seen.eye.angle_deg), distance = float(seen.eye.distance_m), height = float(seen.eye.height_m);
    ImGui::SliderFloat("angle", &angle, -reach, reach, "%.1f deg");
    ImGui::SliderFloat("distance", &distance, 0.1f, 3.0f, "%.2f m", ImGuiSliderFlags_Logarithmic);
    ImGui::SliderFloat("height", &height, -1.0f, 1.0f, "%.2f m");
    seen.eye = SeenFromEye{angle, std::max(distance, 0.01f), height};
    if (images.seen_from) {
      // Recomputed at most 4 times a second, when the frame or the eye moved (seen_from_refresh_due).
      ImGui::Text("updated %.1f s ago (took %.0f ms)", std::max(images.seen_from_age_s, 0.0),
                  images.seen_from_cost_s * 1e3);
      show_texture(*images.seen_from, std::min(ImGui::GetContentRegionAvail().x, float(images.seen_from->width())));
    } else {
      ImGui::TextUnformatted("computing...");
    }
  }
  if (images.quilt) {
    section("Quilt");
    show_texture(*images.quilt, ImGui::GetContentRegionAvail().x);
  }
  end_frame(restore);
  return actions;
}

}  // namespace lfd::viewer
