// raster_mesh.vert: triangles of a mesh object (world space, one vertex per triangle corner so
// that each corner carries its triangle's geometric normal). Three variants, by #define:
// GLOSS_SHADOW_PASS (distance to the light), GLOSS_PER_VERTEX (Gouraud: the contract at the
// vertex), neither (per-pixel: position and normals passed on to raster_mesh.frag).
layout(location = 0) in vec3 gloss_in_position;
layout(location = 1) in vec3 gloss_in_normal;       // shading normal (= face normal when flat)
layout(location = 2) in vec3 gloss_in_face_normal;  // n_g, as wound
// The shadow terminator (src/shading/surface.h, terminator_lift), per corner of a smooth
// triangle (zeros on flat ones): dot(P_j - P_k, n_k) for k = 0, 1, 2 at this corner j, and
// dot(n_k, n_g) times this corner's barycentric weight (one-hot). Interpolated, they give the
// fragment each corner plane's height over it and b_k dot(n_k, n_g).
layout(location = 3) in vec3 gloss_in_terminator_heights;
layout(location = 4) in vec3 gloss_in_terminator_weights;
#if !defined(GLOSS_SHADOW_PASS)
out vec3 gloss_terminator_heights, gloss_terminator_weights;
void gloss_pass_terminator() {
  gloss_terminator_heights = gloss_in_terminator_heights;
  gloss_terminator_weights = gloss_in_terminator_weights;
}
#endif
#if GLOSS_MAPS
// The maps' attributes (raster_geometry.cpp): (u, v) of sets 0 and 1, set 0's tangent and
// handedness, and per triangle (equal at its three corners) set 0's dp/du and dp/dv, each with
// a set's density rho in w (set 0's with dp/du).
layout(location = 5) in vec2 gloss_in_uv0;
layout(location = 6) in vec2 gloss_in_uv1;
layout(location = 7) in vec4 gloss_in_tangent;
layout(location = 8) in vec4 gloss_in_dpdu_density0;
layout(location = 9) in vec4 gloss_in_dpdv_density1;
// The triangle's corners and their (u, v) (set 0's three, then set 1's), the same at each
// corner: the fragment shader intersects its pixel's ray with them.
layout(location = 10) in vec3 gloss_in_p0;
layout(location = 11) in vec3 gloss_in_p1;
layout(location = 12) in vec3 gloss_in_p2;
layout(location = 13) in vec4 gloss_in_corner_uv_a;  // set 0: corner 0, corner 1
layout(location = 14) in vec4 gloss_in_corner_uv_b;  // set 0: corner 2; set 1: corner 0
layout(location = 15) in vec4 gloss_in_corner_uv_c;  // set 1: corner 1, corner 2
out vec2 gloss_uv0, gloss_uv1;
flat out vec3 gloss_p0, gloss_p1, gloss_p2;
flat out vec4 gloss_corner_uv_a, gloss_corner_uv_b, gloss_corner_uv_c;
#if !defined(GLOSS_SHADOW_PASS)
out vec4 gloss_tangent;
flat out vec2 gloss_density;
flat out vec3 gloss_dpdu, gloss_dpdv;
#endif
void gloss_pass_maps() {
  gloss_uv0 = gloss_in_uv0;
  gloss_uv1 = gloss_in_uv1;
  gloss_p0 = gloss_in_p0;
  gloss_p1 = gloss_in_p1;
  gloss_p2 = gloss_in_p2;
  gloss_corner_uv_a = gloss_in_corner_uv_a;
  gloss_corner_uv_b = gloss_in_corner_uv_b;
  gloss_corner_uv_c = gloss_in_corner_uv_c;
#if !defined(GLOSS_SHADOW_PASS)
  gloss_tangent = gloss_in_tangent;
  gloss_density = vec2(gloss_in_dpdu_density0.w, gloss_in_dpdv_density1.w);
  gloss_dpdu = gloss_in_dpdu_density0.xyz;
  gloss_dpdv = gloss_in_dpdv_density1.xyz;
#endif
}
#else
void gloss_pass_maps() {}
#endif

#if defined(GLOSS_SHADOW_PASS)
out vec3 gloss_position;
void main() {
  gloss_position = gloss_in_position;
  gloss_pass_maps();
  gl_Position = gloss_project(gloss_in_position);
}
#elif GLOSS_PER_VERTEX
// Gouraud, as the reference path's gouraud option (reference/reference_renderer.h): each
// corner's unshadowed per-light weights (diffuse: ndl att; specular: att c^alpha) at the
// corner's position and normal, interpolated by the rasterizer (perspective-correct: the hit's
// barycentrics), clamped at 0 and multiplied by the pixel's own shadow test in
// raster_mesh.frag. Every corner of a triangle takes the same side (the eye is on one side of
// its plane), as the reference flips all three by the pixel's side.
out vec3 gloss_position;
flat out vec3 gloss_face_normal;
#if GLOSS_LIGHT_COUNT > 0
out vec2 gloss_light_weights[GLOSS_LIGHT_COUNT];  // (diffuse, specular) of each light
#endif
#if GLOSS_ENVIRONMENT
out vec3 gloss_env_diffuse_weight, gloss_env_specular_weight;  // at the corner, before kd, ks
#endif
void main() {
  vec3 p = gloss_in_position;
  vec3 n_g = gloss_in_face_normal;
  vec3 n = normalize(gloss_in_normal);
  vec3 v = normalize(gloss_view_origin - p);
  gloss_two_sided(n_g, n, v);
#if GLOSS_LIGHT_COUNT > 0
  for (int i = 0; i < GLOSS_LIGHT_COUNT; ++i) {
    GlossLightFactors f = gloss_light(i, p, n, v, 1.0);
    float c = gloss_model_cosine(f, gloss_model);
    gloss_light_weights[i] =
        vec2(f.diffuse_weight, f.spec_weight * gloss_specular_power(c, gloss_alpha));
  }
#endif
#if GLOSS_ENVIRONMENT
  // The environment's fast path at the corner, as gloss_shade takes it per pixel.
  gloss_env_diffuse_weight = gloss_env_diffuse(n) * gloss_env_intensity;
  float env_alpha = gloss_model == GLOSS_PHONG ? gloss_alpha : 0.25 * gloss_alpha;
  gloss_env_specular_weight =
      gloss_env_specular(env_alpha, normalize(2.0 * dot(n, v) * n - v)) * gloss_env_intensity;
#endif
  gloss_position = p;
  gloss_face_normal = gloss_in_face_normal;
  gloss_pass_maps();
  gloss_pass_terminator();
  gl_Position = gloss_project(p);
}
#else
out vec3 gloss_position, gloss_normal;
flat out vec3 gloss_face_normal;
void main() {
  gloss_position = gloss_in_position;
  gloss_normal = gloss_in_normal;
  gloss_face_normal = gloss_in_face_normal;
  gloss_pass_maps();
  gloss_pass_terminator();
  gl_Position = gloss_project(gloss_in_position);
}
#endif
