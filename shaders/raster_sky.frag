// raster_sky.frag: the environment as the background: the map towards this pixel centre's
// camera ray (the camera formula, as raster_sphere.frag casts it), times the intensity, in the
// total; 0 in the terms (docs/spec/shading.md: a miss adds nothing to them).
uniform vec2 gloss_image_size;  // W, H in pixels
layout(location = 0) out vec4 gloss_out_total;
layout(location = 1) out vec4 gloss_out_emissive;
layout(location = 2) out vec4 gloss_out_ambient;
layout(location = 3) out vec4 gloss_out_diffuse;
layout(location = 4) out vec4 gloss_out_specular;
void main() {
  vec2 s = vec2(gl_FragCoord.x * (2.0 / gloss_image_size.x) - 1.0,
                1.0 - gl_FragCoord.y * (2.0 / gloss_image_size.y)) * gloss_view_scale;
  vec3 d = normalize(gloss_view_forward + s.x * gloss_view_right + s.y * gloss_view_up);
#if GLOSS_ENVIRONMENT
  gloss_out_total = vec4(gloss_env_radiance(d) * gloss_env_intensity, 1.0);
#else
  gloss_out_total = vec4(0.0, 0.0, 0.0, 1.0);
#endif
  gloss_out_emissive = gloss_out_ambient = gloss_out_diffuse = gloss_out_specular =
      vec4(0.0, 0.0, 0.0, 1.0);
}
