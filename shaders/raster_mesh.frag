// raster_mesh.frag: the fragment half of raster_mesh.vert's three variants. The shading passes
// write the total and the four term buffers to colour attachments 0..4 (the order of the
// exported shader, editor/model/export/glsl_export.h); the shadow pass writes the distance to the
// light.
#if defined(GLOSS_SHADOW_PASS)
in vec3 gloss_position;
layout(location = 0) out float gloss_distance;
void main() {
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
  // The terms of phong_contract.glsl's gloss_shade with the interpolated weights in place of the
  // pixel's own (raster_mesh.vert), in the same order.
  vec3 n_g = gloss_face_normal;
  if (dot(n_g, gloss_view_origin - gloss_position) < 0.0) n_g = -n_g;
  vec3 ambient_light = gloss_scene_ambient;
  vec3 diffuse = vec3(0.0), specular = vec3(0.0);
  float norm = gloss_energy_normalize ? gloss_energy_normalization(gloss_model, gloss_alpha) : 1.0;
#if GLOSS_LIGHT_COUNT > 0
  for (int i = 0; i < GLOSS_LIGHT_COUNT; ++i) {
    ambient_light += gloss_light_ambient[i];
    vec2 w = max(gloss_light_weights[i], vec2(0.0));
    if (!(w.x > 0.0 || w.y > 0.0)) continue;  // unlit at every corner: no shadow test needed
    float vis = gloss_visibility(i, gloss_position, n_g);
    diffuse += gloss_kd * gloss_light_diffuse[i] * (w.x * vis);
    specular += gloss_ks * gloss_light_specular[i] * (w.y * vis * norm);
  }
#endif
#if GLOSS_ENVIRONMENT
  diffuse += gloss_kd * gloss_env_diffuse_weight;
  specular += gloss_ks * gloss_env_specular_weight;
#endif
  vec3 ambient = gloss_ka * ambient_light;
  gloss_out_total = vec4(((gloss_ke + ambient) + diffuse) + specular, 1.0);
  gloss_out_emissive = vec4(gloss_ke, 1.0);
  gloss_out_ambient = vec4(ambient, 1.0);
  gloss_out_diffuse = vec4(diffuse, 1.0);
  gloss_out_specular = vec4(specular, 1.0);
}
#else
in vec3 gloss_position, gloss_normal;
flat in vec3 gloss_face_normal;
void main() {
  // The interpolated normal renormalised, as the ray tracer does with the barycentric blend of
  // the corner normals at its hit.
  GlossTerms t = gloss_shade(gloss_position, gloss_face_normal, normalize(gloss_normal),
                             gloss_view_origin);
  gloss_out_total = vec4(t.total, 1.0);
  gloss_out_emissive = vec4(t.emissive, 1.0);
  gloss_out_ambient = vec4(t.ambient, 1.0);
  gloss_out_diffuse = vec4(t.diffuse, 1.0);
  gloss_out_specular = vec4(t.specular, 1.0);
}
#endif
#endif
