// raster_common.glsl: what every raster program (src/editor/gl/raster/raster_programs.h) shares:
// the uniforms that phong_contract.glsl expects, the projections, the sphere intersection and the
// shadow-map visibility. Placed after the program's #version and #defines, before the contract.
// The program defines GLOSS_LIGHT_COUNT (0 allowed) and GLOSS_SHADOWS (0 or 1).

// Which kinds of shadow map the program looks up (a shading pass) or draws (a shadow pass: the
// orthographic kind, or the two perspective ones): a raster program defines these
// (raster_programs.h); undefined, all three. As with the light types (phong_contract.glsl), a
// kind the pass has no map of would cost every fragment on llvmpipe, which evaluates both sides
// of a branch on a uniform (a shadow pass's distance: 3 to 5 ms of a light drag's 6 cube faces).
#ifndef GLOSS_SHADOW_CUBE_MAPS
#define GLOSS_SHADOW_CUBE_MAPS 1
#endif
#ifndef GLOSS_SHADOW_PERSPECTIVE_MAPS
#define GLOSS_SHADOW_PERSPECTIVE_MAPS 1
#endif
#ifndef GLOSS_SHADOW_ORTHOGRAPHIC_MAPS
#define GLOSS_SHADOW_ORTHOGRAPHIC_MAPS 1
#endif
#define GLOSS_SHADOW_SINGLE_MAPS (GLOSS_SHADOW_PERSPECTIVE_MAPS || GLOSS_SHADOW_ORTHOGRAPHIC_MAPS)

// The contract's inputs (phong_contract.glsl, header), set per object and per frame.
uniform vec3 gloss_ka, gloss_kd, gloss_ks, gloss_ke;
uniform float gloss_alpha;
uniform vec3 gloss_scene_ambient;
// The model and the normalisation switch are constants of the program (GLOSS_MODEL,
// GLOSS_ENERGY_NORMALIZE, raster_programs.h), as in an exported shader: on a uniform llvmpipe
// computed both models' cosines for every light at every fragment.
const int gloss_model = GLOSS_MODEL;
const bool gloss_energy_normalize = GLOSS_ENERGY_NORMALIZE != 0;
#if GLOSS_LIGHT_COUNT > 0
uniform vec3 gloss_light_position[GLOSS_LIGHT_COUNT];
uniform vec3 gloss_light_ambient[GLOSS_LIGHT_COUNT];
uniform vec3 gloss_light_diffuse[GLOSS_LIGHT_COUNT];
uniform vec3 gloss_light_specular[GLOSS_LIGHT_COUNT];
uniform vec3 gloss_light_attenuation[GLOSS_LIGHT_COUNT];
uniform vec3 gloss_light_direction[GLOSS_LIGHT_COUNT];
uniform vec4 gloss_light_cone[GLOSS_LIGHT_COUNT];
#endif
#if GLOSS_ENVIRONMENT
// environment.glsl's inputs: the levels' atlas (texture unit 1), their places in it (12 levels
// and the map itself), the rotation's (cos, sin) and the intensity.
uniform sampler2D gloss_env_atlas;
uniform ivec4 gloss_env_level[13];
uniform vec2 gloss_env_rotation;
uniform float gloss_env_intensity;
#endif

#if GLOSS_MAPS
// The object's maps (texture_lookup.glsl says what each is); the raster path binds an empty
// texture to the slots the material has none for.
uniform sampler2D gloss_map_diffuse, gloss_map_ambient, gloss_map_specular, gloss_map_emission;
uniform sampler2D gloss_map_shininess, gloss_map_opacity, gloss_map_normal, gloss_map_bump;
uniform bool gloss_map_present[8];
uniform ivec2 gloss_map_wrap[8];
uniform vec4 gloss_map_transform[8];
uniform vec2 gloss_map_offset[8];
uniform ivec2 gloss_map_info[8];
uniform bool gloss_map_alpha[8];
uniform int gloss_map_filter;
uniform float gloss_normal_scale, gloss_bump_scale;
uniform float gloss_cone_spread;
#endif

// The view this pass draws from: the camera (docs/spec/shading.md, "The camera": forward f,
// right r, up u, and the image-plane scales tan(fov_y / 2) W / H and tan(fov_y / 2)), one
// face of a light's cube (scales 1: a 90 degree square frustum), a spot's square frustum
// (scales tan(cutoff)), or, orthographic, a directional light's box across the scene (scales:
// half its width and height in world units; the origin a corner plane's centre before it).
uniform vec3 gloss_view_origin;
uniform vec3 gloss_view_forward, gloss_view_right, gloss_view_up;
uniform vec2 gloss_view_scale;
uniform vec2 gloss_view_depth;  // (A, B): clip z = A w + B maps w = near..far to -1..1
uniform bool gloss_view_ortho;  // orthographic: no division by w

// Clip coordinates of world point p in the pass's view. w is the distance along forward, so the
// rasterizer's perspective division gives the camera formula's (sx, sy) exactly: a pixel centre
// the ray tracer shoots its ray through is the pixel centre GL covers. y is negated so that GL's
// row 0 is the image's top row (frames are read back top row first, base/image.h).
vec4 gloss_project(vec3 p) {
  vec3 d = p - gloss_view_origin;
  float w = dot(d, gloss_view_forward);
  return vec4(dot(d, gloss_view_right) / gloss_view_scale.x,
              -dot(d, gloss_view_up) / gloss_view_scale.y,
              gloss_view_depth.x * w + gloss_view_depth.y, gloss_view_ortho ? 1.0 : w);
}

// The distance a shadow pass stores for world point p: from the light for a perspective view
// (a cube face, a spot), along the light's way from the box's front plane for an orthographic
// one (a directional light).
float gloss_view_distance(vec3 p) {
  vec3 d = p - gloss_view_origin;
#if !GLOSS_SHADOW_ORTHOGRAPHIC_MAPS
  return length(d);
#elif !(GLOSS_SHADOW_CUBE_MAPS || GLOSS_SHADOW_PERSPECTIVE_MAPS)
  return dot(d, gloss_view_forward);
#else
  return gloss_view_ortho ? dot(d, gloss_view_forward) : length(d);
#endif
}

// Window depth (glDepthRange 0..1) of world point p: what gloss_project gives it after the
// division, for impostors that write gl_FragDepth.
float gloss_window_depth(vec3 p) {
  vec4 c = gloss_project(p);
  return 0.5 * (c.z / c.w) + 0.5;
}

// Nearest t > 0 along the unit ray o + t d on the sphere (centre, radius), or -1. The
// discriminant as r^2 - |oc - b d|^2 keeps its precision when the sphere is far away and small
// (no difference of two large squares).
float gloss_sphere_t(vec3 o, vec3 d, vec3 centre, float radius) {
  vec3 oc = o - centre;
  float b = dot(oc, d);
  vec3 closest = oc - b * d;
  float disc = radius * radius - dot(closest, closest);
  if (disc < 0.0) return -1.0;
  float root = sqrt(disc);
  if (-b - root > 0.0) return -b - root;
  return -b + root > 0.0 ? -b + root : -1.0;
}

// The cube face of direction d (from a light), and d in that face's frame: faces 0..5 look
// along +x, -x, +y, -y, +z, -z with (right, up) = +x: (-z, y), -x: (z, y), +y: (x, -z),
// -y: (x, z), +z: (x, y), -z: (-x, y) (raster_view.cpp, cube_face_view, draws face k with that
// frame, so the lookup below finds the texel that face's rasterizer wrote for d). right_up: d's
// components along the face's right and up; major: along its forward, > 0 unless d = 0. Written
// with the components rather than three frame vectors: llvmpipe runs every branch's side, and
// this is most of the shadow test's cost.
int gloss_cube_face(vec3 d, out vec2 right_up, out float major) {
  vec3 a = abs(d);
  if (a.x >= a.y && a.x >= a.z) {
    major = a.x;
    right_up = vec2(d.x >= 0.0 ? -d.z : d.z, d.y);
    return d.x >= 0.0 ? 0 : 1;
  }
  if (a.y >= a.z) {
    major = a.y;
    right_up = vec2(d.x, d.y >= 0.0 ? -d.z : d.z);
    return d.y >= 0.0 ? 2 : 3;
  }
  major = a.z;
  right_up = vec2(d.z >= 0.0 ? d.x : -d.x, d.y);
  return d.z >= 0.0 ? 4 : 5;
}

#define GLOSS_SHADOW_CUBE 0
#define GLOSS_SHADOW_PERSPECTIVE 1
#define GLOSS_SHADOW_ORTHOGRAPHIC 2

// A mesh fragment's terminator lift (raster_mesh.frag sets it; 0 elsewhere), world units.
float gloss_surface_lift = 0.0;

#if GLOSS_SHADOWS && GLOSS_LIGHT_COUNT > 0
// The layers of light i's maps (shadow_maps.h): six cube faces from gloss_shadow_layout[i].x
// for a point light and a spot wider than 60 degrees, or one map: a spot's square frustum along
// its axis, a directional light's orthographic box across the scene. Per texel the distance the
// shadow pass stored (gloss_view_distance), world units.
uniform sampler2DArray gloss_shadow_maps;
uniform float gloss_shadow_size;  // texels per map side
uniform float gloss_shadow_bias;  // texels' worth of depth (raster_settings.h)
uniform ivec2 gloss_shadow_layout[GLOSS_LIGHT_COUNT];  // (first layer, GLOSS_SHADOW_* kind)
// The single map's view (raster_view.h, RasterView); unused for cubes.
uniform vec3 gloss_shadow_origin[GLOSS_LIGHT_COUNT];
uniform vec3 gloss_shadow_forward[GLOSS_LIGHT_COUNT];
uniform vec3 gloss_shadow_right[GLOSS_LIGHT_COUNT];
uniform vec3 gloss_shadow_up[GLOSS_LIGHT_COUNT];
uniform vec2 gloss_shadow_scale[GLOSS_LIGHT_COUNT];

// The contract's vis (shadow rays replaced by a shadow map: docs/spec/shading.md, "A raster
// (GLSL) path"): 1 when p is no farther from light i than the nearest surface the map saw in
// p's direction, plus the bias. A texel spans `texel` world units across at p; a surface at
// angle theta to the light changes depth by tan(theta) of that across it, so the bias grows
// with the slope (capped at 10: at grazing light the diffuse term is near 0 anyway).
float gloss_visibility(int light, vec3 p, vec3 n_g) {
  ivec2 layout_i = gloss_shadow_layout[light];
  // As the ray tracer's shadow ray (src/shading/surface.h shadow_ray_origin): looked up from the
  // smooth surface where the triangle faces away from the light, from the triangle where it
  // faces it by dot(n_g, l) >= 0.1, blended between.
  if (gloss_surface_lift > 0.0) {
    vec3 l = layout_i.y == GLOSS_SHADOW_ORTHOGRAPHIC ? -gloss_shadow_forward[light]
                                                     : gloss_light_position[light] - p;
    float share = clamp(1.0 - dot(n_g, l) / max(0.1 * length(l), 1e-30), 0.0, 1.0);
    p += n_g * (gloss_surface_lift * share);
  }
  int kind = layout_i.y;
  vec2 uv;
  int layer = layout_i.x;
  float dist, texel;
  vec3 towards;  // from the light to p, unit (the slope of the bias)
  // Only the kinds the program declares are compiled in (GLOSS_SHADOW_*_MAPS, above).
#if GLOSS_SHADOW_CUBE_MAPS
#if GLOSS_SHADOW_SINGLE_MAPS
  if (kind == GLOSS_SHADOW_CUBE) {
#else
  {
#endif
    vec3 d = p - gloss_light_position[light];
    dist = length(d);
    // d = 0 (a light on the surface) has no direction to look up: lit, as the ray tracer's
    // shadow segment of length 0 finds nothing.
    if (!(dist > 0.0)) return 1.0;
    vec2 right_up;
    float major;
    layer += gloss_cube_face(d, right_up, major);
    uv = right_up / major * 0.5 + 0.5;
    texel = 2.0 * dist / gloss_shadow_size;
    towards = d / dist;
  }
#endif
#if GLOSS_SHADOW_CUBE_MAPS && GLOSS_SHADOW_SINGLE_MAPS
  else
#endif
#if GLOSS_SHADOW_SINGLE_MAPS
  {
    vec3 d = p - gloss_shadow_origin[light];
    float w = dot(d, gloss_shadow_forward[light]);
    vec2 across = vec2(dot(d, gloss_shadow_right[light]), dot(d, gloss_shadow_up[light]));
    vec2 scale = gloss_shadow_scale[light];
#if GLOSS_SHADOW_ORTHOGRAPHIC_MAPS && GLOSS_SHADOW_PERSPECTIVE_MAPS
    if (kind == GLOSS_SHADOW_ORTHOGRAPHIC) {
#elif GLOSS_SHADOW_ORTHOGRAPHIC_MAPS
    {
#endif
#if GLOSS_SHADOW_ORTHOGRAPHIC_MAPS
      uv = across / scale * 0.5 + 0.5;
      dist = w;
      texel = 2.0 * max(scale.x, scale.y) / gloss_shadow_size;
      towards = gloss_shadow_forward[light];
    }
#endif
#if GLOSS_SHADOW_ORTHOGRAPHIC_MAPS && GLOSS_SHADOW_PERSPECTIVE_MAPS
    else
#endif
#if GLOSS_SHADOW_PERSPECTIVE_MAPS
    {
      // Behind the spot or outside its frustum the spot factor is 0 (nothing to shadow).
      if (!(w > 0.0)) return 1.0;
      uv = across / (w * scale) * 0.5 + 0.5;
      dist = length(d);
      texel = 2.0 * w * max(scale.x, scale.y) / gloss_shadow_size;
      towards = d / dist;
    }
#endif
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 1.0;
  }
#endif
  int size = int(gloss_shadow_size);
  ivec2 at = clamp(ivec2(floor(uv * gloss_shadow_size)), ivec2(0), ivec2(size - 1));
  // The pass drew with y negated (gloss_project): row 0 is the map's top.
  at.y = size - 1 - at.y;
  float stored = texelFetch(gloss_shadow_maps, ivec3(at, layer), 0).r;
  float cos_theta = abs(dot(n_g, towards));
  float tan_theta = sqrt(max(1.0 - cos_theta * cos_theta, 0.0)) / max(cos_theta, 1e-6);
  float bias = gloss_shadow_bias * texel * min(1.0 + tan_theta, 10.0);
  return dist <= stored + bias ? 1.0 : 0.0;
}
#else
float gloss_visibility(int light, vec3 p, vec3 n_g) {
  return 1.0;
}
#endif
