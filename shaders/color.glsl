// Colour helpers of the display shader (tonemap.comp). They have no C++ twin: what
// they compute is checked where images are compared, GPU against GPU, bit for bit.
#ifndef RAYLAB_COLOR_GLSL
#define RAYLAB_COLOR_GLSL

// Narkowicz's fit of the ACES filmic curve: keeps highlights from clipping abruptly.
vec3 acesFilm(vec3 x) {
  x = max(x, vec3(0.0));
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

vec3 linearToSrgb(vec3 c) {
  vec3 lo = 12.92 * c;
  vec3 hi = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
  return mix(lo, hi, greaterThan(c, vec3(0.0031308)));
}

uint packDisplayColor(vec3 linearRgb) {
  vec3 s = linearToSrgb(acesFilm(linearRgb));
  uvec3 b = uvec3(clamp(s * 255.0 + 0.5, 0.0, 255.0));
  return b.r | (b.g << 8) | (b.b << 16) | (255u << 24);
}

#endif
