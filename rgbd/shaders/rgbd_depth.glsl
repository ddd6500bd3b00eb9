// GLSL twin of rgbd::decode_depth (rgbd/rgbd_frame.cpp, docs/rgbd.md "Chroma depth"): the
// normalised depth (1 = near) of a depth-half texel, grey or hue, then inverted if asked.
const float kChromaFarHue = 2.0 / 3.0;

float decode_depth(vec3 c, bool chroma_depth, bool depth_inversion) {
  float d;
  if (!chroma_depth) {
    d = (c.r + c.g + c.b) / 3.0;
  } else {
    const float mx = max(c.r, max(c.g, c.b)), mn = min(c.r, min(c.g, c.b));
    const float range = mx - mn;
    if (range <= 0.0) {
      d = 0.0;
    } else {
      float h;
      if (mx == c.r) h = (c.g - c.b) / range;
      else if (mx == c.g) h = 2.0 + (c.b - c.r) / range;
      else h = 4.0 + (c.r - c.g) / range;
      h /= 6.0;
      if (h < 0.0) h += 1.0;
      if (h > kChromaFarHue) h = h > 0.5 * (1.0 + kChromaFarHue) ? 0.0 : kChromaFarHue;
      d = 1.0 - h / kChromaFarHue;
    }
  }
  d = clamp(d, 0.0, 1.0);
  return depth_inversion ? 1.0 - d : d;
}
