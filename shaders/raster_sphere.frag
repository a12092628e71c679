// raster_sphere.frag: a sphere as an impostor. Shading passes cast the camera ray of this
// pixel's centre (the camera formula of docs/spec/shading.md with the pixel's own coordinates,
// as the ray tracer does), so silhouette and normal are the ray tracer's at pixel centres; the
// hit's depth goes to gl_FragDepth so spheres and meshes hide each other correctly. The shadow
// pass casts from the light through the box fragment and writes the hit's distance.
in vec3 gloss_position;
uniform vec3 gloss_sphere_centre;
uniform float gloss_sphere_radius;

// The nearest t along o + t d on the sphere where it is a surface: the near root, or, where an
// opacity map cuts it out there, the far one (the inside seen through the hole); -1 for none.
float gloss_sphere_surface_t(vec3 o, vec3 d) {
  float t = gloss_sphere_t(o, d, gloss_sphere_centre, gloss_sphere_radius);
#if GLOSS_MAPS
  if (t < 0.0 || !gloss_map_present[GLOSS_MAP_OPACITY]) return t;
  vec3 p = o + t * d;
  if (gloss_opaque_at(gloss_map_opacity, GLOSS_MAP_OPACITY,
                      gloss_sphere_uv(normalize(p - gloss_sphere_centre)))) {
    return t;
  }
  // The far root: past the near one by the chord.
  vec3 oc = o - gloss_sphere_centre;
  float b = dot(oc, d);
  vec3 closest = oc - b * d;
  float far = -b + sqrt(max(gloss_sphere_radius * gloss_sphere_radius - dot(closest, closest),
                            0.0));
  if (!(far > t)) return -1.0;
  p = o + far * d;
  return gloss_opaque_at(gloss_map_opacity, GLOSS_MAP_OPACITY,
                         gloss_sphere_uv(normalize(p - gloss_sphere_centre)))
             ? far
             : -1.0;
#else
  return t;
#endif
}

#if defined(GLOSS_SHADOW_PASS)
layout(location = 0) out float gloss_distance;
void main() {
  // From the light through the fragment; orthographic: along the light's way from where the
  // fragment's parallel ray crosses the view's front plane.
  // (Only the kinds of view the pass draws: raster_common.glsl, GLOSS_SHADOW_*_MAPS.)
  vec3 o = gloss_view_origin;
  vec3 d = normalize(gloss_position - gloss_view_origin);
#if GLOSS_SHADOW_ORTHOGRAPHIC_MAPS
#if GLOSS_SHADOW_CUBE_MAPS || GLOSS_SHADOW_PERSPECTIVE_MAPS
  if (gloss_view_ortho)
#endif
  {
    d = gloss_view_forward;
    o = gloss_position - dot(gloss_position - gloss_view_origin, d) * d;
  }
#endif
  float t = gloss_sphere_surface_t(o, d);
  if (t < 0.0) discard;
  gl_FragDepth = gloss_window_depth(o + t * d);
  gloss_distance = gloss_view_distance(o + t * d);
}
#else
uniform vec2 gloss_image_size;  // W, H in pixels
layout(location = 0) out vec4 gloss_out_total;
layout(location = 1) out vec4 gloss_out_emissive;
layout(location = 2) out vec4 gloss_out_ambient;
layout(location = 3) out vec4 gloss_out_diffuse;
layout(location = 4) out vec4 gloss_out_specular;
void main() {
  // gl_FragCoord is (x + 0.5, y + 0.5) for pixel (x, y), y from the top (gloss_project).
  vec2 s = vec2(gl_FragCoord.x * (2.0 / gloss_image_size.x) - 1.0,
                1.0 - gl_FragCoord.y * (2.0 / gloss_image_size.y)) * gloss_view_scale;
  vec3 d = normalize(gloss_view_forward + s.x * gloss_view_right + s.y * gloss_view_up);
  float t = gloss_sphere_surface_t(gloss_view_origin, d);
  if (t < 0.0) discard;
  vec3 p = gloss_view_origin + t * d;
  vec3 n = (p - gloss_sphere_centre) / gloss_sphere_radius;
  gl_FragDepth = gloss_window_depth(p);
#if GLOSS_MAPS
  vec3 v = -d;
  float side = dot(n, v) < 0.0 ? -1.0 : 1.0;
  vec3 n_v = side * n;
  GlossMapFrame f = gloss_sphere_frame(gloss_sphere_centre, gloss_sphere_radius, p, t, d);
  f.n = n_v;
  f.v = v;
  f.side = side;
  GlossMapValues m = gloss_map_values(f);
  GlossTerms terms = gloss_shade_at(p, n_v, m.n, v, gloss_ka * m.ka, gloss_kd * m.kd,
                                    gloss_ks * m.ks, gloss_ke * m.ke, gloss_alpha * m.alpha);
#else
  GlossTerms terms = gloss_shade(p, n, n, gloss_view_origin);
#endif
  gloss_out_total = vec4(terms.total, 1.0);
  gloss_out_emissive = vec4(terms.emissive, 1.0);
  gloss_out_ambient = vec4(terms.ambient, 1.0);
  gloss_out_diffuse = vec4(terms.diffuse, 1.0);
  gloss_out_specular = vec4(terms.specular, 1.0);
}
#endif
