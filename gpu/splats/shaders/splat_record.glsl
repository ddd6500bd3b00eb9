// One projected Gaussian (gpu/splats/gl_splat_preprocess.hpp SplatRecord), std430, 64 bytes.
// #included by the splat shaders that read or write records.
struct SplatRecord {
  vec4 mean_depth_opacity;  // mean_px.xy (pixel (i, j) centred at (i, j), row 0 = top), view z, opacity
  vec4 conic_radius;        // conic (xx, xy, yy), radius_px (0: culled)
  vec4 color;               // rgb, w unused
  ivec4 rect;               // tile rectangle: min.xy, max.xy (exclusive)
};
