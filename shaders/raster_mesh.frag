// raster_mesh.frag: the fragment half of raster_mesh.vert's three variants. The shading passes
// write the total and the four term buffers to colour attachments 0..4 (the order of the
// exported shader, editor/model/export/glsl_export.h); the shadow pass writes the distance to the
// light.
#if GLOSS_MAPS
in vec2 gloss_uv0, gloss_uv1;
flat in vec3 gloss_p0, gloss_p1, gloss_p2;
flat in vec4 gloss_corner_uv_a, gloss_corner_uv_b, gloss_corner_uv_c;
uniform vec2 gloss_image_size;  // W, H in pixels

// The hit's (u, v) of both sets from the barycentrics of this pixel's camera ray against the
// triangle (Moller-Trumbore, as the ray tracer finds them), not the rasterizer's interpolation,
// whose rounding shows on a map's sharp edges. Shadow passes (no camera ray) interpolate.
void gloss_hit_uv(out vec2 uv0, out vec2 uv1) {
#if defined(GLOSS_SHADOW_PASS)
  uv0 = gloss_uv0;
  uv1 = gloss_uv1;
#else
  vec2 s = vec2(gl_FragCoord.x * (2.0 / gloss_image_size.x) - 1.0,
                1.0 - gl_FragCoord.y * (2.0 / gloss_image_size.y)) * gloss_view_scale;
  vec3 d = normalize(gloss_view_forward + s.x * gloss_view_right + s.y * gloss_view_up);
  vec3 e1 = gloss_p1 - gloss_p0, e2 = gloss_p2 - gloss_p0;
  vec3 pvec = cross(d, e2);
  float det = dot(e1, pvec);
  if (!(abs(det) > 1e-12 * length(e1) * length(e2))) {  // edge-on: the interpolated ones
    uv0 = gloss_uv0;
    uv1 = gloss_uv1;
    return;
  }
  vec3 tvec = gloss_view_origin - gloss_p0;
  float u = dot(tvec, pvec) / det;
  float v = dot(d, cross(tvec, e1)) / det;
  float w = 1.0 - u - v;
  uv0 = w * gloss_corner_uv_a.xy + u * gloss_corner_uv_a.zw + v * gloss_corner_uv_b.xy;
  uv1 = w * gloss_corner_uv_b.zw + u * gloss_corner_uv_c.xy + v * gloss_corner_uv_c.zw;
#endif
}
#if !defined(GLOSS_SHADOW_PASS)
in vec4 gloss_tangent;
flat in vec2 gloss_density;
flat in vec3 gloss_dpdu, gloss_dpdv;
#endif
// A cut-out: no surface where the opacity map is below 0.5 (shadow passes too).
void gloss_cut_out() {
  if (!gloss_map_present[GLOSS_MAP_OPACITY]) return;
  vec2 uv0, uv1;
  gloss_hit_uv(uv0, uv1);
  vec2 uv = gloss_map_info[GLOSS_MAP_OPACITY].x == 1 ? uv1 : uv0;
  if (!gloss_opaque_at(gloss_map_opacity, GLOSS_MAP_OPACITY, uv)) discard;
}
#if !defined(GLOSS_SHADOW_PASS)
// The maps at this fragment: its (u, v), the ray cone's footprint, its tangent frame.
// n_g and n are on the viewer's side already; side says whether they were turned.
GlossMapValues gloss_fragment_maps(vec3 p, vec3 n_g, vec3 n, vec3 v, float side) {
  GlossMapFrame f;
  gloss_hit_uv(f.uv[0], f.uv[1]);
  float t = length(p - gloss_view_origin);
  float cos_theta = dot(v, n_g);
  f.footprint[0] = gloss_footprint(t, cos_theta, gloss_density.x);
  f.footprint[1] = gloss_footprint(t, cos_theta, gloss_density.y);
  f.n = n;
  f.v = v;
  f.side = side;
  f.tangent = gloss_tangent.xyz;
  f.handedness = gloss_tangent.w < 0.0 ? -1.0 : 1.0;
  f.dpdu = gloss_dpdu;
  f.dpdv = gloss_dpdv;
  return gloss_map_values(f);
}
#endif
#else
void gloss_cut_out() {}
#endif

#if !defined(GLOSS_SHADOW_PASS)
in vec3 gloss_terminator_heights, gloss_terminator_weights;  // raster_mesh.vert
// The smooth surface's height over the triangle here (src/shading/surface.h terminator_lift):
// sum_k b_k max(0, -side dot(p - P_k, n_k)) dot(n_k, n_g), which gloss_visibility takes in
// part or whole (raster_common.glsl, gloss_surface_lift). side: -1 where n_g was turned;
// has_normal: false where the corner normals cancel (the ray tracer then shades and shadows from the
// face: surface.h), known per pixel only (per vertex takes true).
void gloss_set_terminator_lift(float side, bool has_normal) {
  vec3 below = max(vec3(0.0), -side * gloss_terminator_heights);
  gloss_surface_lift = has_normal ? max(0.0, dot(below, gloss_terminator_weights)) : 0.0;
}
#endif

#if defined(GLOSS_SHADOW_PASS)
in vec3 gloss_position;
layout(location = 0) out float gloss_distance;
void main() {
  gloss_cut_out();
  gloss_distance = gloss_view_distance(gloss_position);
}
#else
layout(location = 0) out vec4 gloss_out_total;
layout(location = 1) out vec4 gloss_out_emissive;
layout(location = 2) out vec4 gloss_out_ambient;
layout(location = 3) out vec4 gloss_out_diffuse;
layout(location = 4) out vec4 gloss_out_specular;
#if GLOSS_PER_VERTEX
in vec3 gloss_position;
flat in vec3 gloss_face_normal;
#if GLOSS_LIGHT_COUNT > 0
in vec2 gloss_light_weights[GLOSS_LIGHT_COUNT];
#endif
#if GLOSS_ENVIRONMENT
in vec3 gloss_env_diffuse_weight, gloss_env_specular_weight;
#endif
void main() {
  gloss_cut_out();
  // The terms of phong_contract.glsl's gloss_shade with the interpolated weights in place of the
  // pixel's own (raster_mesh.vert), in the same order.
  vec3 n_g = gloss_face_normal;
  float side = 1.0;
  if (dot(n_g, gloss_view_origin - gloss_position) < 0.0) {
    n_g = -n_g;
    side = -1.0;
  }
  gloss_set_terminator_lift(side, true);
  vec3 ka = gloss_ka, kd = gloss_kd, ks = gloss_ks, ke = gloss_ke;
#if GLOSS_MAPS
  // The colour maps per fragment; the weights (and so the exponent and the normal) are the
  // corners' (a shininess or normal map does not reach per-vertex shading).
  GlossMapValues m = gloss_fragment_maps(gloss_position, n_g, n_g,
                                         normalize(gloss_view_origin - gloss_position), side);
  ka *= m.ka;
  kd *= m.kd;
  ks *= m.ks;
  ke *= m.ke;
#endif
  vec3 ambient_light = gloss_scene_ambient;
  vec3 diffuse = vec3(0.0), specular = vec3(0.0);
  float norm = gloss_energy_normalize ? gloss_energy_normalization(gloss_model, gloss_alpha) : 1.0;
#if GLOSS_LIGHT_COUNT > 0
  for (int i = 0; i < GLOSS_LIGHT_COUNT; ++i) {
    ambient_light += gloss_light_ambient[i];
    vec2 w = max(gloss_light_weights[i], vec2(0.0));
    if (!(w.x > 0.0 || w.y > 0.0)) continue;  // unlit at every corner: no shadow test needed
    float vis = gloss_visibility(i, gloss_position, n_g);
    diffuse += kd * gloss_light_diffuse[i] * (w.x * vis);
    specular += ks * gloss_light_specular[i] * (w.y * vis * norm);
  }
#endif
#if GLOSS_ENVIRONMENT
  diffuse += kd * gloss_env_diffuse_weight;
  specular += ks * gloss_env_specular_weight;
#endif
  vec3 ambient = ka * ambient_light;
  gloss_out_total = vec4(((ke + ambient) + diffuse) + specular, 1.0);
  gloss_out_emissive = vec4(ke, 1.0);
  gloss_out_ambient = vec4(ambient, 1.0);
  gloss_out_diffuse = vec4(diffuse, 1.0);
  gloss_out_specular = vec4(specular, 1.0);
}
#else
in vec3 gloss_position, gloss_normal;
flat in vec3 gloss_face_normal;
void main() {
  gloss_cut_out();
  gloss_set_terminator_lift(
      dot(gloss_face_normal, gloss_view_origin - gloss_position) < 0.0 ? -1.0 : 1.0,
      length(gloss_normal) > 1e-6);
  // The interpolated normal renormalised, as the ray tracer does with the barycentric blend of
  // the corner normals at its hit.
#if GLOSS_MAPS
  vec3 v = normalize(gloss_view_origin - gloss_position);
  vec3 n_g = gloss_face_normal, n = normalize(gloss_normal);
  float side = dot(n_g, v) < 0.0 ? -1.0 : 1.0;
  n_g *= side;
  n *= side;
  GlossMapValues m = gloss_fragment_maps(gloss_position, n_g, n, v, side);
  GlossTerms t = gloss_shade_at(gloss_position, n_g, m.n, v, gloss_ka * m.ka, gloss_kd * m.kd,
                                gloss_ks * m.ks, gloss_ke * m.ke, gloss_alpha * m.alpha);
#else
  GlossTerms t = gloss_shade(gloss_position, gloss_face_normal, normalize(gloss_normal),
                             gloss_view_origin);
#endif
  gloss_out_total = vec4(t.total, 1.0);
  gloss_out_emissive = vec4(t.emissive, 1.0);
  gloss_out_ambient = vec4(t.ambient, 1.0);
  gloss_out_diffuse = vec4(t.diffuse, 1.0);
  gloss_out_specular = vec4(t.specular, 1.0);
}
#endif
#endif
