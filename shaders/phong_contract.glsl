// phong_contract.glsl: the shading contract of docs/spec/shading.md, written once in GLSL.
// The same rules as src/shading/shading.h and src/shading/total.h (the CPU and reference paths).
//
// Subset: GLSL 3.30 core and GLSL ES 3.00 (WebGL 2) alike: no #version line here (the program
// that uses this file puts its own first), no derivatives, no integer bit operations, no
// double. float arithmetic throughout (the CPU path computes the per-light factors in double;
// docs/spec/shading.md, "A raster (GLSL) path", counts float arithmetic as a measured knob).
//
// What a program must define BEFORE this code (an exported shader,
// editor/model/export/glsl_export.h, defines all of them as constants):
//   GLOSS_LIGHT_COUNT                  a #define, number of lights (0 allowed)
//   vec3 gloss_ka, gloss_kd, gloss_ks, gloss_ke   material constants ("The terms and the total")
//   float gloss_alpha                  shininess exponent, >= 0
//   vec3 gloss_scene_ambient           A_scene
//   int gloss_model                    GLOSS_PHONG or GLOSS_BLINN_PHONG
//   bool gloss_energy_normalize        the "Optional switches" energy normalisation
//   and, when GLOSS_LIGHT_COUNT > 0, arrays of GLOSS_LIGHT_COUNT entries:
//   vec3 gloss_light_position[], gloss_light_ambient[], gloss_light_diffuse[],
//        gloss_light_specular[], gloss_light_attenuation[] (c0, c1, c2)
//   vec3 gloss_light_direction[]       unit, world space, the way the light travels
//                                      (directional and spot lights; a headlight's already
//                                      turned into the camera's frame)
//   vec4 gloss_light_cone[]            (type: GLOSS_POINT, GLOSS_DIRECTIONAL or GLOSS_SPOT,
//                                      1 - cos(cutoff), 1 - cos(min(inner, cutoff)), exponent),
//                                      the cosines as 1 - cos so that a cone of 0.01 degrees
//                                      (cos = 1 - 1.5e-8, 1 in float) keeps its size
//   float gloss_visibility(int light, vec3 p, vec3 n_g)   vis: 1 lit, 0 shadowed
//   GLOSS_ENVIRONMENT                  a #define, 1 with an environment light (environment.glsl
//                                      included before this file and its inputs defined)
// and it may define GLOSS_POINT_LIGHTS, GLOSS_DIRECTIONAL_LIGHTS and GLOSS_SPOT_LIGHTS (0 or 1,
// 1 when left undefined) to leave out the code of light types it has no light of.

// Which light types the program handles: a raster program defines these three from its scene's
// lights (raster_programs.h), an exported shader leaves them undefined (all three). A branch on
// a uniform costs both its sides on llvmpipe, so a type no light has would cost every fragment.
#ifndef GLOSS_POINT_LIGHTS
#define GLOSS_POINT_LIGHTS 1
#endif
#ifndef GLOSS_DIRECTIONAL_LIGHTS
#define GLOSS_DIRECTIONAL_LIGHTS 1
#endif
#ifndef GLOSS_SPOT_LIGHTS
#define GLOSS_SPOT_LIGHTS 1
#endif

#define GLOSS_PHONG 0
#define GLOSS_BLINN_PHONG 1
#define GLOSS_POINT 0
#define GLOSS_DIRECTIONAL 1
#define GLOSS_SPOT 2

// What one point light contributes at one point, before material constants and light colours
// (shading.h, LightFactors): diffuse = kd Ld diffuse_weight, specular = ks Ls spec_weight c^alpha.
struct GlossLightFactors {
  float diffuse_weight;  // ndl * att * vis, 0 when ndl <= 0
  float spec_weight;     // att * vis, 0 when ndl <= 0
  float cos_phong;       // R . V = dot(2 ndl n - l, v)
  float cos_blinn;       // N . H = dot(n, normalize(l + v))
};

// The four term contributions and their total at one point ("Term buffers").
struct GlossTerms {
  vec3 emissive;
  vec3 ambient;
  vec3 diffuse;   // summed over the lights
  vec3 specular;  // summed over the lights
  vec3 total;
};

// "What one point light adds": att = 1 / (c0 + c1 d + c2 d^2); c >= 0, not all 0 (the loader
// refuses others), so the denominator is > 0.
float gloss_attenuation(vec3 c, float d) {
  return 1.0 / (c.x + d * (c.y + d * c.z));
}

// "The surface at a hit": every surface has two sides; when dot(n_g, v) < 0 both n_g and n are
// negated before any rule uses them. Spheres seen from outside never flip; meshes can.
void gloss_two_sided(inout vec3 n_g, inout vec3 n, vec3 v) {
  if (dot(n_g, v) < 0.0) {
    n_g = -n_g;
    n = -n;
  }
}

// The geometric factors of light arriving along unit l with weight att (times the spot factor),
// at a point with unit shading normal n and unit v, both on the viewer's side (shading.h,
// factors_along). ndl <= 0: all factors 0.
GlossLightFactors gloss_factors_along(vec3 n, vec3 v, vec3 l, float att, float vis) {
  GlossLightFactors f = GlossLightFactors(0.0, 0.0, 0.0, 0.0);
  float ndl = dot(n, l);       // ndl = dot(n, l)
  if (!(ndl > 0.0)) return f;  // ndl <= 0: neither diffuse nor specular
  f.spec_weight = att * vis;                        // specular_i carries att * spot * vis
  f.diffuse_weight = ndl * f.spec_weight;           // diffuse_i = kd Ld ndl att spot vis
  f.cos_phong = dot(2.0 * ndl * n - l, v);          // Phong: R . V, R = 2 ndl n - l
  vec3 h = l + v;                                   // l = -v leaves no half vector (shading.h)
  float h_len = length(h);
  f.cos_blinn = h_len > 0.0 ? dot(n, h) / h_len : 0.0;  // Blinn-Phong: N . normalize(l + v)
  return f;
}

// "What one point light adds", the geometric part (shading.h, light_factors). p: point, n: unit
// shading normal, v: unit direction to the eye, both already on the viewer's side; vis 1 or 0.
// A light exactly at p (d = 0) or with ndl <= 0 adds nothing: all factors 0.
GlossLightFactors gloss_light_factors(vec3 p, vec3 n, vec3 v, vec3 light_position,
                                      vec3 attenuation_coeffs, float vis) {
  vec3 to_light = light_position - p;
  float d = length(to_light);  // d = |P_i - p|
  if (!(d > 0.0)) return GlossLightFactors(0.0, 0.0, 0.0, 0.0);  // a light on the surface
  return gloss_factors_along(n, v, to_light / d, gloss_attenuation(attenuation_coeffs, d), vis);
}

// log(1 - x) for 0 <= x <= 2, accurate where 1 - x rounds to 1 in float (a series below 1e-3).
float gloss_log_one_minus(float x) {
  return x < 1e-3 ? -x * (1.0 + x * (0.5 + x / 3.0)) : log(max(1.0 - x, 0.0));
}

// "Light types", the spot factor: cos_t = dot(-l, s) against the cone (1 - cos values, as
// gloss_light_cone gives them): 0 outside, else cos_t^exponent times the smooth edge's
// clamp(...)^2 (light_source.h, spot_factor). 1 - cos_t is half the squared chord between the
// unit vectors -l and s, exact in float for the narrowest cones.
float gloss_spot_factor(vec3 l, vec3 s, vec4 cone) {
  vec3 chord = -l - s;
  float vers_t = 0.5 * dot(chord, chord);  // 1 - cos_t
  if (vers_t > cone.y) return 0.0;         // cos_t < cos(cutoff): outside the cone
  // cos_t^exponent (x^0 = 1); cos_t >= cos(cutoff) >= 0 here.
  float spot = cone.w == 0.0 ? 1.0 : exp(cone.w * gloss_log_one_minus(vers_t));
  float width = cone.y - cone.z;  // cos(inner) - cos(cutoff)
  if (width > 1e-6) {
    float e = clamp((cone.y - vers_t) / width, 0.0, 1.0);  // (cos_t - cos(cutoff)) / width
    spot *= e * e;
  }
  return spot;
}

#if GLOSS_LIGHT_COUNT > 0
// Light i of any type at p (light_source.h, source_factors): a point light as above; a
// directional light from l = -D everywhere with att = 1; a spot as a point light times the
// spot factor. Only the types the program declares (GLOSS_*_LIGHTS) are compiled in.
GlossLightFactors gloss_light(int i, vec3 p, vec3 n, vec3 v, float vis) {
  vec4 cone = gloss_light_cone[i];
  int type = int(cone.x + 0.5);
#if GLOSS_DIRECTIONAL_LIGHTS
#if GLOSS_POINT_LIGHTS || GLOSS_SPOT_LIGHTS
  if (type == GLOSS_DIRECTIONAL)
#endif
  {
    return gloss_factors_along(n, v, -gloss_light_direction[i], 1.0, vis);
  }
#endif
#if GLOSS_POINT_LIGHTS || GLOSS_SPOT_LIGHTS
  vec3 to_light = gloss_light_position[i] - p;
  float d = length(to_light);
  if (!(d > 0.0)) return GlossLightFactors(0.0, 0.0, 0.0, 0.0);  // a light on the surface
  vec3 l = to_light / d;
  float att = gloss_attenuation(gloss_light_attenuation[i], d);
#if GLOSS_SPOT_LIGHTS && GLOSS_POINT_LIGHTS
  if (type == GLOSS_SPOT) att *= gloss_spot_factor(l, gloss_light_direction[i], cone);
#elif GLOSS_SPOT_LIGHTS
  att *= gloss_spot_factor(l, gloss_light_direction[i], cone);
#endif
  return gloss_factors_along(n, v, l, att, vis);
#endif
}
#endif

// "The terms and the total": c^alpha for c > 0, 0 for c <= 0; at alpha = 0, 1 wherever c > 0
// (the specular term is continuous as alpha goes to 0). c above 1 comes from rounding only.
float gloss_specular_power(float c, float alpha) {
  if (!(c > 0.0)) return 0.0;
  if (c >= 1.0) return 1.0;
  if (alpha == 0.0) return 1.0;
  return pow(c, alpha);  // defined: 0 < c < 1
}

// The cosine the model raises to alpha (shading.h, model_cosine).
float gloss_model_cosine(GlossLightFactors f, int model) {
  return model == GLOSS_PHONG ? f.cos_phong : f.cos_blinn;
}

// "Optional switches": the specular term times (alpha + 2) / (2 pi) for Phong, times
// (alpha + 8) / (8 pi) for Blinn-Phong.
float gloss_energy_normalization(int model, float alpha) {
  const float pi = 3.14159265358979323846;
  return model == GLOSS_PHONG ? (alpha + 2.0) / (2.0 * pi) : (alpha + 8.0) / (8.0 * pi);
}

// The contract at one surface point with the given material values (the constants, or the
// constants times what maps give there: texture_lookup.glsl). p: world position; n_g and n:
// geometric and shading normal, unit, both already on the viewer's side; v: unit, to the eye.
GlossTerms gloss_shade_at(vec3 p, vec3 n_g, vec3 n, vec3 v, vec3 ka, vec3 kd, vec3 ks, vec3 ke,
                          float alpha) {
  GlossTerms t;
  t.emissive = ke;  // emissive = ke
  vec3 ambient_light = gloss_scene_ambient;
  t.diffuse = vec3(0.0);
  t.specular = vec3(0.0);
  float norm = gloss_energy_normalize ? gloss_energy_normalization(gloss_model, alpha) : 1.0;
#if GLOSS_LIGHT_COUNT > 0
  for (int i = 0; i < GLOSS_LIGHT_COUNT; ++i) {
    ambient_light += gloss_light_ambient[i];  // A_scene + sum_i La_i: not attenuated, not shadowed
    float vis = gloss_visibility(i, p, n_g);
    GlossLightFactors f = gloss_light(i, p, n, v, vis);
    float c = gloss_model_cosine(f, gloss_model);
    // diffuse_i = kd * Ld_i * ndl * att * spot * vis
    t.diffuse += kd * gloss_light_diffuse[i] * f.diffuse_weight;
    // specular_i = ks * Ls_i * c^alpha * att * spot * vis (times the normalisation when on)
    t.specular += ks * gloss_light_specular[i] * (f.spec_weight *
                                                  gloss_specular_power(c, alpha) * norm);
  }
#endif
#if GLOSS_ENVIRONMENT
  // The environment's fast path (environment.glsl): kd E(n) / pi and ks times the lobe's mean
  // about the mirror direction, at the intensity (no energy normalisation: the lobe is normalised).
  vec3 mirror = normalize(2.0 * dot(n, v) * n - v);
  float env_alpha = gloss_model == GLOSS_PHONG ? alpha : 0.25 * alpha;
  t.diffuse += kd * (gloss_env_diffuse(n) * gloss_env_intensity);
  t.specular += ks * (gloss_env_specular(env_alpha, mirror) * gloss_env_intensity);
#endif
  t.ambient = ka * ambient_light;  // ambient = ka * (A_scene + sum_i La_i)
  // total = emissive + ambient + sum_i (diffuse_i + specular_i), in total.h's fixed order
  t.total = ((t.emissive + t.ambient) + t.diffuse) + t.specular;
  return t;
}

// The whole contract at one surface point with the material and lights defined above.
// p: world position; n_g: geometric normal; n: shading normal (unit; n = n_g on spheres and flat
// meshes); eye: camera position. The two-sided rule is applied here.
GlossTerms gloss_shade(vec3 p, vec3 n_g, vec3 n, vec3 eye) {
  vec3 v = normalize(eye - p);  // v = normalize(eye - p)
  gloss_two_sided(n_g, n, v);
  return gloss_shade_at(p, n_g, n, v, gloss_ka, gloss_kd, gloss_ks, gloss_ke, gloss_alpha);
}
