// environment.glsl: the environment light's fast path (docs/engine.md, "The environment";
// src/engine/environment/prefiltered_environment.h and src/shading/environment.h), written once
// in GLSL: the same prefiltered levels, the same bilinear lookups between texel centres
// (wrapping around horizontally, clamped at the poles) and the same blend between levels in
// log2 alpha, so the raster path and an exported shader agree with the ray tracer's fast path.
// Like it, this knows no horizon, no visibility and no Blinn-Phong view dependence (it takes the
// Phong level of alpha / 4): docs/accuracy.md measures what that costs.
//
// Included after the program's #defines and before phong_contract.glsl, whose gloss_shade adds
// the environment's terms when GLOSS_ENVIRONMENT is 1. A program must then define:
//   sampler2D gloss_env_atlas          every level and the map itself in one RGB float texture
//                                      (read with texelFetch only)
//   ivec4 gloss_env_level[GLOSS_ENV_LEVELS + 1]   (x, y, width, height) of level k in the atlas,
//                                      the last entry the map itself
//   vec2 gloss_env_rotation           (cos, sin) of the rotation about +y
//   float gloss_env_intensity         the radiance scale

#define GLOSS_ENV_LEVELS 12  // alpha 0, 1, 2, 4, ... 1024

#if GLOSS_ENVIRONMENT
// w turned by -rotation about +y: the direction in the map's own frame.
vec3 gloss_env_to_map(vec3 w) {
  vec2 r = gloss_env_rotation;
  return vec3(w.x * r.x - w.z * r.y, w.y, w.x * r.y + w.z * r.x);
}

// atan(y / x) in (-pi, pi] to about 1e-7 relative. GLSL sets no precision for its atan and acos
// (llvmpipe's move a lookup on a light's sharp edge by more than 1e-3 of its value), so they are
// computed here as the C library does: Cephes' atanf, reduced to |t| <= tan(pi / 8).
float gloss_env_atan2(float y, float x) {
  float ay = abs(y), ax = abs(x);
  bool swap = ay > ax;
  float t = swap ? ax / ay : ay / ax;  // in [0, 1]
  float base = 0.0;
  if (t > 0.41421356) {
    base = 0.78539816;
    t = (t - 1.0) / (t + 1.0);
  }
  float z = t * t;
  float a = base + ((((8.05374449538e-2 * z - 1.38776856032e-1) * z + 1.99777106478e-1) * z -
                     3.33329491539e-1) * z * t + t);
  if (swap) a = 1.57079633 - a;
  if (x < 0.0) a = 3.14159265 - a;
  return y < 0.0 ? -a : a;
}

// (u, t) of a unit map-frame direction: u = 0.5 + atan2(x, -z) / (2 pi), t = acos(y) / pi; at
// the poles (x = z = 0) u = 0.5, as shading/environment.h. acos(y) as atan2(sqrt(1 - y^2), y)
// with 1 - y^2 as (1 - y)(1 + y), exact near the poles.
vec2 gloss_env_uv(vec3 m) {
  const float pi = 3.14159265358979323846;
  float phi = m.x == 0.0 && m.z == 0.0 ? 0.0 : gloss_env_atan2(m.x, -m.z);
  float y = clamp(m.y, -1.0, 1.0);
  float theta = gloss_env_atan2(sqrt((1.0 - y) * (1.0 + y)), y);
  return vec2(0.5 + phi / (2.0 * pi), theta / pi);
}

// Level k at (u, t), bilinear between texel centres.
vec3 gloss_env_bilinear(int k, vec2 uv) {
  ivec4 level = gloss_env_level[k];
  float x = uv.x * float(level.z) - 0.5, y = uv.y * float(level.w) - 0.5;
  float fx = floor(x), fy = floor(y);
  float ax = x - fx, ay = y - fy;
  int i0 = int(fx) % level.z;
  if (i0 < 0) i0 += level.z;
  int i1 = i0 + 1 == level.z ? 0 : i0 + 1;
  int j0 = clamp(int(fy), 0, level.w - 1), j1 = clamp(int(fy) + 1, 0, level.w - 1);
  vec3 a = texelFetch(gloss_env_atlas, level.xy + ivec2(i0, j0), 0).rgb;
  vec3 b = texelFetch(gloss_env_atlas, level.xy + ivec2(i1, j0), 0).rgb;
  vec3 c = texelFetch(gloss_env_atlas, level.xy + ivec2(i0, j1), 0).rgb;
  vec3 d = texelFetch(gloss_env_atlas, level.xy + ivec2(i1, j1), 0).rgb;
  vec3 top = a * (1.0 - ax) + b * ax, bottom = c * (1.0 - ax) + d * ax;
  return top * (1.0 - ay) + bottom * ay;
}

// The map's radiance towards world direction w, intensity 1 (the background).
vec3 gloss_env_radiance(vec3 w) {
  return gloss_env_bilinear(GLOSS_ENV_LEVELS, gloss_env_uv(gloss_env_to_map(w)));
}

// The diffuse term's irradiance / pi at unit normal n: level 1 (the clamped cosine).
vec3 gloss_env_diffuse(vec3 n) {
  return gloss_env_bilinear(1, gloss_env_uv(gloss_env_to_map(n)));
}

// The specular term's lobe mean of exponent alpha about unit r: the two levels around alpha in
// log2 alpha; above 1024 towards the map itself, reached at 16384.
vec3 gloss_env_specular(float alpha, vec3 r) {
  vec2 uv = gloss_env_uv(gloss_env_to_map(r));
  int last = GLOSS_ENV_LEVELS - 1;
  int a = 0, b = 0;
  float wb = 0.0;
  if (!(alpha > 0.0)) {
  } else if (alpha < 1.0) {
    b = 1;
    wb = alpha;
  } else if (alpha <= 1024.0) {
    float k = log2(alpha);
    a = min(last, 1 + int(floor(k)));
    b = a == last ? a : a + 1;
    wb = a == last ? 0.0 : k - floor(k);
  } else {
    a = last;
    b = GLOSS_ENV_LEVELS;
    wb = min(log2(alpha / 1024.0) / log2(16.0), 1.0);
  }
  vec3 la = gloss_env_bilinear(a, uv);
  return wb == 0.0 ? la : la + (gloss_env_bilinear(b, uv) - la) * wb;
}
#endif
