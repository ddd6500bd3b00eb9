// One splat blended into one pixel by the reference's rules (renderCUDA in forward.cu; the CPU's
// render/blend.cpp), for the compute tile rasterizer's compositing (splat_tile_composite,
// splat_tile_merge): skip power > 0 and alpha < 1/255, alpha clamped at 0.99, and stop before T
// would fall under 1e-4. Returns false when the pixel stops there (the splat is not blended).
bool blend_splat(vec2 mean, vec4 conic_opacity, vec3 color, vec2 pixf, inout vec3 C, inout float T) {
  vec2 d = mean - pixf;
  vec4 co = conic_opacity;
  float power = -0.5 * (co.x * d.x * d.x + co.z * d.y * d.y) - co.y * d.x * d.y;
  if (power > 0.0) return true;
  float alpha = min(0.99, co.w * exp(power));
  if (alpha < 1.0 / 255.0) return true;
  float test_T = T * (1.0 - alpha);
  if (test_T < 0.0001) return false;
  float w = alpha * T;
  C += color * w;
  T = test_T;
  return true;
}
