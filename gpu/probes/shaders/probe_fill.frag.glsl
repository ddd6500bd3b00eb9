// The throughput probe's raster fill: a faint colour blended as the splats blend, so each
// fragment is a read-modify-write of the RGBA16F target in the ROPs.
layout(location = 0) out vec4 colour;
void main() { colour = vec4(0.01, 0.02, 0.03, 0.01); }
