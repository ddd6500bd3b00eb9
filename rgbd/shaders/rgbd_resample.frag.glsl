// Stage 1 of RGB-D to quilt (twin of rgbd::resample_rgbd, rgbd/rgbd_quilt.cpp): the colour
// (bilinear) and depth (nearest) halves at tile resolution through zoom and crop, read in place
// from the frame through their rectangles. Target: tile-size RGBA32F, rgb = colour, a = depth.
// Rectangles and rows are top-down like the CPU's; the frame texture is bottom-up unless
// frame_top_down.
#include "rgbd/shaders/rgbd_io.h"
#include "rgbd/shaders/rgbd_depth.glsl"

layout(binding = kRgbdFrameUnit) uniform sampler2D frame;
uniform ivec4 colour_rect;  // x, y (top-down), width, height
uniform ivec4 depth_rect;
uniform int frame_height;
uniform bool frame_top_down;  // texel row 0 is the picture's top row
uniform ivec2 tile_size;
uniform vec2 crop;          // crop_pos_x, -crop_pos_y (top-down)
uniform float zoom;
uniform bool chroma_depth;
uniform bool depth_inversion;
uniform float depth_cutoff;  // depths below it are removed (black), keeping their depth

out vec4 result;

vec3 texel(ivec4 rect, int x, int y) {
  const int row = rect.y + y;
  return texelFetch(frame, ivec2(rect.x + x, frame_top_down ? row : frame_height - 1 - row), 0).rgb;
}

void main() {
  const int x = int(gl_FragCoord.x);
  const int y = tile_size.y - 1 - int(gl_FragCoord.y);  // top-down row
  const float su = 0.5 + 0.5 * crop.x + ((float(x) + 0.5) / float(tile_size.x) - 0.5) / zoom;
  const float sv = 0.5 + 0.5 * crop.y + ((float(y) + 0.5) / float(tile_size.y) - 0.5) / zoom;
  if (!(su >= 0.0 && su < 1.0 && sv >= 0.0 && sv < 1.0)) {
    result = vec4(0.0);  // zoomed or cropped out: black, far
    return;
  }
  const vec2 p = vec2(su * float(colour_rect.z), sv * float(colour_rect.w)) - 0.5;
  const vec2 f = floor(p);
  const vec2 t = p - f;
  const int x0 = clamp(int(f.x), 0, colour_rect.z - 1), x1 = clamp(int(f.x) + 1, 0, colour_rect.z - 1);
  const int y0 = clamp(int(f.y), 0, colour_rect.w - 1), y1 = clamp(int(f.y) + 1, 0, colour_rect.w - 1);
  const vec3 top = texel(colour_rect, x0, y0) + (texel(colour_rect, x1, y0) - texel(colour_rect, x0, y0)) * t.x;
  const vec3 bot = texel(colour_rect, x0, y1) + (texel(colour_rect, x1, y1) - texel(colour_rect, x0, y1)) * t.x;
  const vec3 colour = top + (bot - top) * t.y;
  const int dx = min(int(su * float(depth_rect.z)), depth_rect.z - 1);
  const int dy = min(int(sv * float(depth_rect.w)), depth_rect.w - 1);
  const float d = decode_depth(texel(depth_rect, dx, dy), chroma_depth, depth_inversion);
  result = vec4(d < depth_cutoff ? vec3(0.0) : colour, d);
}
