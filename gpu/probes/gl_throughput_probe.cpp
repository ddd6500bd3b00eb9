#include "gpu/probes/gl_throughput_probe.hpp"

#include <algorithm>
#include <chrono>
#include <functional>
#include <vector>

#include <epoxy/gl.h>

#include "gpu/gl/gl_objects.hpp"
#include "gpu/gl/gl_program.hpp"
#include "gpu/probes/shaders/probe_copy.comp.glsl.hpp"
#include "gpu/probes/shaders/probe_fill.frag.glsl.hpp"
#include "gpu/probes/shaders/probe_fill.vert.glsl.hpp"
#include "gpu/probes/shaders/probe_fma.comp.glsl.hpp"
#include "gpu/probes/shaders/probe_io.h"

namespace lfd::gpu {
namespace {

double median_seconds(const ThroughputProbeOptions& o, const std::function<void()>& work) {
  std::vector<double> seconds;
  for (int run = 0; run < o.warmup + o.runs; ++run) {
    glFinish();
    const auto t0 = std::chrono::steady_clock::now();
    work();
    glFinish();
    if (run >= o.warmup) seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(seconds.begin(), seconds.end());
  return seconds[seconds.size() / 2];
}

}  // namespace

ThroughputProbe probe_throughput(const ThroughputProbeOptions& o) {
  ThroughputProbe p;
  {
    Program fma("probe: fma", {{GL_COMPUTE_SHADER, probe_fma_comp_glsl}}, {},
                {storage_buffer("result", kProbeTargetBinding, Access::write)});
    Buffer out(o.invocations * 4);
    glProgramUniform1ui(fma.id(), fma.uniform("iterations"), o.fma_iterations);
    glProgramUniform1f(fma.id(), fma.uniform("seed"), 1e-3f);
    p.fma_s = median_seconds(o, [&] {
      fma.bind("result", out);
      fma.use();
      fma.dispatch_1d(o.invocations, int(kProbeGroupSize));
    });
    p.fma_gflops = double(o.invocations) * o.fma_iterations * 8 * 2 / p.fma_s / 1e9;
  }
  {
    Program copy("probe: copy", {{GL_COMPUTE_SHADER, probe_copy_comp_glsl}}, {},
                 {storage_buffer("source", kProbeSourceBinding, Access::read),
                  storage_buffer("target", kProbeTargetBinding, Access::write)});
    const size_t count = o.copy_bytes / 16;
    Buffer source(count * 16), target(count * 16);
    glProgramUniform1ui(copy.id(), copy.uniform("count"), GLuint(count));
    p.copy_s = median_seconds(o, [&] {
      copy.bind("source", source);
      copy.bind("target", target);
      copy.use();
      copy.dispatch_1d(count, int(kProbeGroupSize));
    });
    p.bandwidth_gbs = 2.0 * double(count * 16) / p.copy_s / 1e9;
  }
  {
    Program fill("probe: fill", {{GL_VERTEX_SHADER, probe_fill_vert_glsl}, {GL_FRAGMENT_SHADER, probe_fill_frag_glsl}});
    Texture target(GL_RGBA16F, o.fill_size, o.fill_size);
    Framebuffer framebuffer;
    framebuffer.attach(0, target);
    framebuffer.finish(1);
    VertexArray vertices;
    p.fill_s = median_seconds(o, [&] {
      glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
      glViewport(0, 0, o.fill_size, o.fill_size);
      glEnable(GL_BLEND);
      glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
      glBindVertexArray(vertices.id());
      fill.use();
      fill.draw_arrays(GL_TRIANGLES, 0, 3, o.fill_layers);
      glDisable(GL_BLEND);
      glBindVertexArray(0);
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
    });
    p.fill_gpixels = double(o.fill_size) * o.fill_size * o.fill_layers / p.fill_s / 1e9;
  }
  check_gl("the throughput probe");
  return p;
}

}  // namespace lfd::gpu
