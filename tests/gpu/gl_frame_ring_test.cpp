// What a frame leaves for the CPU without waiting (gpu/gl/gl_frame_ring.hpp,
// gpu/gl/gl_async_readback.hpp) and the uniform table made at link (gpu/gl/gl_objects.hpp), on llvmpipe.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <thread>
#include <vector>

#include "gpu/gl/gl_async_readback.hpp"
#include "gpu/gl/gl_context.hpp"
#include "gpu/gl/gl_frame_ring.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/gl/gl_program.hpp"

namespace lfd::gpu {
namespace {

TEST(GlFrameRing, ReadsTheNewestFinishedFrameLateWithItsCopiedBytes) {
  HeadlessContext context;
  GlFrameRing ring(3, 8);
  EXPECT_FALSE(ring.newest_ready());  // nothing rendered yet
  for (uint32_t frame = 1; frame <= 4; ++frame) {
    const uint32_t words[2] = {frame, 1000 + frame};
    Buffer source(sizeof(words), words);
    ring.begin_frame();
    ring.stamp(0);
    ring.stamp(1);
    ring.copy_back(source.id(), 0, sizeof(words), 0);
    ring.stamp(2);
    ring.end_frame();
  }
  // Every frame done: the last frame's fence waited for (fences signal in order). Not glFinish:
  // after the ring's glFlush, zink (Mesa 22.3) returns from glFinish before the flushed frames
  // are done (docs/gpu.md "What zink found").
  ASSERT_TRUE(ring.wait_newest());
  const std::optional<GlFrameReadout> r = ring.newest_ready();  // the newest ready one is the last
  ASSERT_TRUE(r);
  EXPECT_EQ(r->frame, 4u);
  EXPECT_EQ(r->frames_late, 0u);
  ASSERT_EQ(r->stamps_ns.size(), 3u);
  EXPECT_GT(r->stamps_ns[0], 0u);
  EXPECT_LE(r->stamps_ns[0], r->stamps_ns[1]);
  EXPECT_LE(r->stamps_ns[1], r->stamps_ns[2]);
  uint32_t words[2] = {0, 0};
  ASSERT_EQ(r->bytes.size(), sizeof(words));
  std::memcpy(words, r->bytes.data(), sizeof(words));
  EXPECT_EQ(words[0], 4u);
  EXPECT_EQ(words[1], 1004u);
  // A later frame begun but not ended: the readout is one frame late.
  ring.begin_frame();
  const std::optional<GlFrameReadout> late = ring.newest_ready();
  ASSERT_TRUE(late);
  EXPECT_EQ(late->frame, 4u);
  EXPECT_EQ(late->frames_late, 1u);
  ring.end_frame();
  EXPECT_EQ(ring.wait_newest()->frame, 5u);
}

TEST(GlFrameRing, NeverHasMoreSlotsThanAllowedAndSkipsFramesInsteadOfWaiting) {
  HeadlessContext context;
  GlFrameRing ring(2, 0, 2);
  for (int frame = 0; frame < 10; ++frame) {  // whatever the GPU's progress, no call blocks
    ring.begin_frame();
    ring.stamp(0);
    ring.stamp(1);
    ring.end_frame();
  }
  ASSERT_TRUE(ring.wait_newest());  // the newest recorded frame done (not glFinish: see above)
  const std::optional<GlFrameReadout> r = ring.newest_ready();
  ASSERT_TRUE(r);
  EXPECT_GE(r->frame, 1u);
  EXPECT_LE(r->frame, 10u);
}

TEST(AsyncTextureReadback, ReadsTheTextureTopDownOnceItsFenceSignalled) {
  HeadlessContext context;
  const int w = 5, h = 3;
  std::vector<uint8_t> texels(size_t(w) * h * 4);  // GL rows bottom-up
  for (size_t i = 0; i < texels.size(); ++i) texels[i] = uint8_t(i * 7 + 3);
  Texture texture(GL_RGBA8, w, h);
  glTextureSubImage2D(texture.id(), 0, 0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  AsyncTextureReadback readback;
  EXPECT_FALSE(readback.poll());  // nothing started
  ASSERT_TRUE(readback.start(texture));
  EXPECT_TRUE(readback.busy());
  EXPECT_FALSE(readback.start(texture));  // one at a time
  // Polled as the viewer does, on later frames, until the fence has signalled: glFinish would not
  // do after the readback's glFlush on zink (Mesa 22.3; docs/gpu.md "What zink found").
  std::optional<Image8> image;
  for (int frame = 0; frame < 6000 && !image; ++frame) {
    image = readback.poll();
    if (!image) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_TRUE(image) << "the readback's fence never signalled";
  EXPECT_FALSE(readback.busy());
  ASSERT_EQ(image->width, w);
  ASSERT_EQ(image->height, h);
  ASSERT_EQ(image->channels, 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 4; ++c)
        EXPECT_EQ(image->pixels[(size_t(y) * w + x) * 4 + c], texels[(size_t(h - 1 - y) * w + x) * 4 + c]);
}

TEST(Program, UniformLocationsComeFromTheTableMadeAtLink) {
  HeadlessContext context;
  const char* source = R"(
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer Out { float out_value[]; };
uniform float scale;
uniform vec2 offsets[3];
uniform int unused_by_the_code;
void main() { out_value[0] = scale * offsets[2].y; }
)";
  const Program p("uniform table", {{GL_COMPUTE_SHADER, source}});
  EXPECT_EQ(p.uniform("scale"), glGetUniformLocation(p.id(), "scale"));
  EXPECT_GE(p.uniform("scale"), 0);
  EXPECT_EQ(p.uniform("offsets"), glGetUniformLocation(p.id(), "offsets"));
  EXPECT_EQ(p.uniform("offsets[0]"), glGetUniformLocation(p.id(), "offsets[0]"));
  // Optimised away: -1, or an exception under strict checks (gl_program_test.cpp).
  if (strict_gl_checks()) {
    EXPECT_THROW(p.uniform("unused_by_the_code"), std::logic_error);
  } else {
    EXPECT_EQ(p.uniform("unused_by_the_code"), -1);
  }
  EXPECT_THROW(p.uniform("no_such_uniform"), std::logic_error);  // not in the sources
}

}  // namespace
}  // namespace lfd::gpu
