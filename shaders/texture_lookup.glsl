// texture_lookup.glsl: the contract's texture maps (docs/spec/shading.md, "Textures") in GLSL,
// the same arithmetic as src/texture/texture_lookup.h, src/texture/footprint.h,
// src/shading/texturing.h and src/shading/hit_textures.h: texel centres at
// u = (i + 0.5) / W, v = 1 - (j + 0.5) / H; bilinear weights computed here in fp32 and the
// texels read with texelFetch (not the GPU's filtering, whose weights have 8 bits); trilinear
// between the levels around the ray cone's footprint (not the GPU's derivatives); the wrap
// modes on texel indices. Placed after phong_contract.glsl. Level 0 of each sampler is the
// map's image, row 0 its top row, one float texture level per mip level (RGBA or R).
//
// What a program must define BEFORE this code (the raster path sets them per object, an
// exported shader names them as uniforms):
//   sampler2D gloss_map_<slot>         for each slot of GLOSS_MAP_SLOTS present
//   bool gloss_map_present[8]          by slot: diffuse, ambient, specular, emission, shininess,
//                                      opacity, normal, bump
//   ivec2 gloss_map_wrap[8]            per axis: GLOSS_REPEAT, GLOSS_CLAMP, GLOSS_MIRROR
//   vec4 gloss_map_transform[8]        (scale u, scale v, cos rotation, sin rotation)
//   vec2 gloss_map_offset[8]
//   ivec2 gloss_map_info[8]            (uv set 0 or 1, level count)
//   bool gloss_map_alpha[8]            the image has an alpha channel (opacity reads it)
//   int gloss_map_filter               GLOSS_TRILINEAR, GLOSS_BILINEAR, GLOSS_NEAREST
//   float gloss_normal_scale, gloss_bump_scale
//   float gloss_cone_spread            2 tan(fov_y / 2) / H: one pixel's cone at unit distance

#define GLOSS_REPEAT 0
#define GLOSS_CLAMP 1
#define GLOSS_MIRROR 2
#define GLOSS_TRILINEAR 0
#define GLOSS_BILINEAR 1
#define GLOSS_NEAREST 2
#define GLOSS_MAP_DIFFUSE 0
#define GLOSS_MAP_AMBIENT 1
#define GLOSS_MAP_SPECULAR 2
#define GLOSS_MAP_EMISSION 3
#define GLOSS_MAP_SHININESS 4
#define GLOSS_MAP_OPACITY 5
#define GLOSS_MAP_NORMAL 6
#define GLOSS_MAP_BUMP 7

// Texel index i of a side of n texels (i from gloss_coordinate_range: -n-1 <= i <= 2n + 1).
int gloss_wrap_index(int i, int n, int wrap) {
  if (wrap == GLOSS_CLAMP) return clamp(i, 0, n - 1);
  if (wrap == GLOSS_MIRROR) {
    int m = (i + 4 * n) % (2 * n);
    return m < n ? m : 2 * n - 1 - m;
  }
  return (i + 2 * n) % n;
}

// A coordinate brought into one period of its wrap mode: repeat [0, 1), mirror [0, 2),
// clamp [-1, 2] (texture_lookup.h coordinate_range).
float gloss_coordinate_range(float c, int wrap) {
  if (wrap == GLOSS_CLAMP) return clamp(c, -1.0, 2.0);
  if (wrap == GLOSS_MIRROR) return c - 2.0 * floor(c / 2.0);
  return c - floor(c);
}

vec2 gloss_texel_coordinates(vec2 uv, ivec2 size, ivec2 wrap) {
  float cu = gloss_coordinate_range(uv.x, wrap.x), cv = gloss_coordinate_range(uv.y, wrap.y);
  if (isnan(cu) || isinf(cu)) cu = 0.0;
  if (isnan(cv) || isinf(cv)) cv = 0.0;
  return vec2(cu * float(size.x) - 0.5, (1.0 - cv) * float(size.y) - 0.5);
}

// A level's size: the pyramid halves each side, rounding down, to 1 (texture/mip_pyramid.h),
// as GL's own mip chain does. Computed, not asked of textureSize(s, level): Mesa's llvmpipe
// answered level 0's size for every level (tests/editor/gl/test_raster_maps.cpp found it).
ivec2 gloss_level_size(sampler2D s, int level) {
  return max(ivec2(1), textureSize(s, 0) >> level);
}

vec4 gloss_bilinear(sampler2D s, int level, vec2 uv, ivec2 wrap) {
  ivec2 size = gloss_level_size(s, level);
  vec2 xy = gloss_texel_coordinates(uv, size, wrap);
  vec2 f0 = floor(xy);
  vec2 f = xy - f0;
  int x0 = int(f0.x), y0 = int(f0.y);
  int i0 = gloss_wrap_index(x0, size.x, wrap.x), i1 = gloss_wrap_index(x0 + 1, size.x, wrap.x);
  int j0 = gloss_wrap_index(y0, size.y, wrap.y), j1 = gloss_wrap_index(y0 + 1, size.y, wrap.y);
  vec4 top = texelFetch(s, ivec2(i0, j0), level) * (1.0 - f.x) +
             texelFetch(s, ivec2(i1, j0), level) * f.x;
  vec4 bottom = texelFetch(s, ivec2(i0, j1), level) * (1.0 - f.x) +
                texelFetch(s, ivec2(i1, j1), level) * f.x;
  return top * (1.0 - f.y) + bottom * f.y;
}

vec4 gloss_nearest(sampler2D s, vec2 uv, ivec2 wrap) {
  ivec2 size = textureSize(s, 0);
  vec2 xy = gloss_texel_coordinates(uv, size, wrap);
  int i = gloss_wrap_index(int(floor(xy.x + 0.5)), size.x, wrap.x);
  int j = gloss_wrap_index(int(floor(xy.y + 0.5)), size.y, wrap.y);
  return texelFetch(s, ivec2(i, j), 0);
}

vec4 gloss_trilinear(sampler2D s, int levels, float lod, vec2 uv, ivec2 wrap) {
  float top = float(levels - 1);
  float level = lod > 0.0 ? (lod < top ? lod : top) : 0.0;  // NaN reads level 0
  int l0 = int(floor(level));
  float f = level - float(l0);
  vec4 a = gloss_bilinear(s, l0, uv, wrap);
  if (!(f > 0.0)) return a;
  return a * (1.0 - f) + gloss_bilinear(s, l0 + 1, uv, wrap) * f;
}

// (u, v) as a map reads them: times its scale, turned, plus its offset (scene/texture_map.h).
vec2 gloss_map_coordinates(int slot, vec2 uv) {
  vec4 t = gloss_map_transform[slot];
  vec2 scaled = uv * t.xy;
  return vec2(t.z * scaled.x - t.w * scaled.y, t.w * scaled.x + t.z * scaled.y) +
         gloss_map_offset[slot];
}

// The ray cone's level (texture/footprint.h): log2(footprint) + 0.5 log2(|su sv| W H).
float gloss_map_level(sampler2D s, int slot, float footprint) {
  ivec2 size = textureSize(s, 0);
  vec4 t = gloss_map_transform[slot];
  return log2(footprint) + 0.5 * log2(abs(t.x * t.y) * float(size.x) * float(size.y));
}

vec4 gloss_read_map(sampler2D s, int slot, vec2 uv, float footprint) {
  vec2 m = gloss_map_coordinates(slot, uv);
  ivec2 wrap = gloss_map_wrap[slot];
  if (gloss_map_filter == GLOSS_NEAREST) return gloss_nearest(s, m, wrap);
  if (gloss_map_filter == GLOSS_BILINEAR) return gloss_bilinear(s, 0, m, wrap);
  return gloss_trilinear(s, gloss_map_info[slot].y, gloss_map_level(s, slot, footprint), m, wrap);
}

// The cut-out test: bilinear at level 0, the alpha where the image has one, at least 0.5.
bool gloss_opaque_at(sampler2D s, int slot, vec2 uv) {
  vec4 t = gloss_bilinear(s, 0, gloss_map_coordinates(slot, uv), gloss_map_wrap[slot]);
  return (gloss_map_alpha[slot] ? t.a : t.r) >= 0.5;
}

// The footprint of a sample (texture/footprint.h): t along the unit ray, cos theta against n_g,
// rho the surface's sqrt((u, v) area / world area).
float gloss_footprint(float t, float cos_theta, float rho) {
  float c = abs(cos_theta);
  return t * gloss_cone_spread / (c > 1e-6 ? c : 1e-6) * rho;
}

// shading/texturing.h: any_perpendicular, orthogonal_tangent, tangent_space_normal,
// normal_from_map, normal_from_bump, facing_viewer, bump_step.
vec3 gloss_any_perpendicular(vec3 n) {
  vec3 axis = abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  return normalize(cross(axis, n));
}

vec3 gloss_orthogonal_tangent(vec3 n, vec3 t) {
  vec3 p = t - n * dot(n, t);
  float len = length(p);
  return len > 1e-12 ? p / len : gloss_any_perpendicular(n);
}

vec3 gloss_tangent_space_normal(vec4 texel, float scale) {
  vec3 n = vec3((2.0 * texel.x - 1.0) * scale, (2.0 * texel.y - 1.0) * scale, 2.0 * texel.z - 1.0);
  float len = length(n);
  return len > 0.0 ? n / len : vec3(0.0, 0.0, 1.0);
}

vec3 gloss_normal_from_map(vec3 N, vec3 tangent, float w, vec3 nt) {
  vec3 t = gloss_orthogonal_tangent(N, tangent);
  vec3 b = w * cross(N, t);
  vec3 n = t * nt.x + b * nt.y + N * nt.z;
  float len = length(n);
  return len > 0.0 ? n / len : N;
}

vec3 gloss_normal_from_bump(vec3 N, vec3 dpdu, vec3 dpdv, float h, float h_u, float h_v,
                            float du, float dv) {
  vec3 pu = dpdu - N * dot(N, dpdu) + N * ((h_u - h) / du);
  vec3 pv = dpdv - N * dot(N, dpdv) + N * ((h_v - h) / dv);
  vec3 n = cross(pu, pv);
  float len = length(n);
  if (!(len > 0.0)) return N;
  n /= len;
  return dot(n, N) < 0.0 ? -n : n;
}

vec3 gloss_facing_viewer(vec3 n, vec3 v) {
  float d = dot(n, v);
  if (!(d < 0.0)) return n;
  return normalize(n - 2.0 * d * v);
}

float gloss_bump_step(float footprint) {
  float du = 0.5 * footprint;
  return du > 0.0 ? du : 0.0005;
}

// The surface at a hit as the maps need it (hit_textures.h MapFrame).
struct GlossMapFrame {
  vec2 uv[2];
  float footprint[2];
  vec3 n;        // shading normal on the viewer's side
  vec3 v;
  float side;    // -1 where the two-sided rule turned n around
  vec3 tangent;  // set 0's, as the mesh gives it
  float handedness;
  vec3 dpdu, dpdv;
};

struct GlossMapValues {
  vec3 kd, ka, ks, ke;
  float alpha;
  vec3 n;
};

// What the maps give at a hit (hit_textures.h map_values): the multipliers of kd, ka, ks, ke and
// alpha, and the shading normal after the normal and bump maps, on the viewer's side.
GlossMapValues gloss_map_values(GlossMapFrame f) {
  GlossMapValues o;
  o.kd = vec3(1.0);
  o.ka = vec3(1.0);
  o.ks = vec3(1.0);
  o.ke = vec3(1.0);
  o.alpha = 1.0;
  o.n = f.n;
  if (gloss_map_present[GLOSS_MAP_DIFFUSE]) {
    int set = gloss_map_info[GLOSS_MAP_DIFFUSE].x;
    o.kd = gloss_read_map(gloss_map_diffuse, GLOSS_MAP_DIFFUSE, f.uv[set], f.footprint[set]).rgb;
    o.ka = o.kd;
  }
  if (gloss_map_present[GLOSS_MAP_AMBIENT]) {
    int set = gloss_map_info[GLOSS_MAP_AMBIENT].x;
    o.ka = gloss_read_map(gloss_map_ambient, GLOSS_MAP_AMBIENT, f.uv[set], f.footprint[set]).rgb;
  }
  if (gloss_map_present[GLOSS_MAP_SPECULAR]) {
    int set = gloss_map_info[GLOSS_MAP_SPECULAR].x;
    o.ks = gloss_read_map(gloss_map_specular, GLOSS_MAP_SPECULAR, f.uv[set], f.footprint[set]).rgb;
  }
  if (gloss_map_present[GLOSS_MAP_EMISSION]) {
    int set = gloss_map_info[GLOSS_MAP_EMISSION].x;
    o.ke = gloss_read_map(gloss_map_emission, GLOSS_MAP_EMISSION, f.uv[set], f.footprint[set]).rgb;
  }
  if (gloss_map_present[GLOSS_MAP_SHININESS]) {
    int set = gloss_map_info[GLOSS_MAP_SHININESS].x;
    o.alpha =
        gloss_read_map(gloss_map_shininess, GLOSS_MAP_SHININESS, f.uv[set], f.footprint[set]).r;
  }
  // In the surface's own orientation, then turned with it (a bump on the back is a dent).
  vec3 n0 = f.side * f.n;
  vec3 n = n0;
  if (gloss_map_present[GLOSS_MAP_NORMAL]) {
    int set = gloss_map_info[GLOSS_MAP_NORMAL].x;
    vec4 texel = gloss_read_map(gloss_map_normal, GLOSS_MAP_NORMAL, f.uv[set], f.footprint[set]);
    vec3 nt = gloss_tangent_space_normal(texel, gloss_normal_scale);
    vec4 t = gloss_map_transform[GLOSS_MAP_NORMAL];
    if (t.w != 0.0 || t.x < 0.0 || t.y < 0.0) {  // a turned or mirrored map: its x, y back
      float x = t.z * nt.x + t.w * nt.y, y = -t.w * nt.x + t.z * nt.y;
      nt.x = t.x < 0.0 ? -x : x;
      nt.y = t.y < 0.0 ? -y : y;
    }
    n = gloss_normal_from_map(n, f.tangent, f.handedness, nt);
  }
  if (gloss_map_present[GLOSS_MAP_BUMP]) {
    int set = gloss_map_info[GLOSS_MAP_BUMP].x;
    vec2 uv = f.uv[set];
    float du = gloss_bump_step(f.footprint[set]);
    float h = gloss_bump_scale * gloss_read_map(gloss_map_bump, GLOSS_MAP_BUMP, uv, f.footprint[set]).r;
    float h_u = gloss_bump_scale *
                gloss_read_map(gloss_map_bump, GLOSS_MAP_BUMP, uv + vec2(du, 0.0), f.footprint[set]).r;
    float h_v = gloss_bump_scale *
                gloss_read_map(gloss_map_bump, GLOSS_MAP_BUMP, uv + vec2(0.0, du), f.footprint[set]).r;
    vec3 dpdu = f.dpdu, dpdv = f.dpdv;
    if (length(cross(dpdu, dpdv)) == 0.0) {
      dpdu = gloss_orthogonal_tangent(n, f.tangent);
      dpdv = f.handedness * cross(n, dpdu);
    }
    n = gloss_normal_from_bump(n, dpdu, dpdv, h, h_u, h_v, du, du);
  }
  if (n != n0) o.n = gloss_facing_viewer(f.side * n, f.v);
  return o;
}

// A sphere's (u, v), tangent and density (texture/sphere_mapping.h, texture/footprint.h) from
// the unit direction d from its centre.
vec2 gloss_sphere_uv(vec3 d) {
  const float pi = 3.14159265358979323846;
  return vec2(0.5 + atan(d.x, d.z) / (2.0 * pi), 0.5 + atan(d.y, length(d.xz)) / pi);
}

vec3 gloss_sphere_tangent(vec3 d) {
  float len = sqrt(d.x * d.x + d.z * d.z);
  return len > 1e-12 ? vec3(d.z / len, 0.0, -d.x / len) : vec3(1.0, 0.0, 0.0);
}

float gloss_sphere_density(float radius, float y) {
  const float pi = 3.14159265358979323846;
  float c2 = 1.0 - y * y;
  float cos_beta = sqrt(c2 > 1e-12 ? c2 : 1e-12);
  return 1.0 / (radius * sqrt(2.0 * cos_beta) * pi);
}

// The frame of a sphere hit at p seen along the unit ray d from distance t.
GlossMapFrame gloss_sphere_frame(vec3 centre, float radius, vec3 p, float t, vec3 ray) {
  const float pi = 3.14159265358979323846;
  GlossMapFrame f;
  vec3 d = normalize(p - centre);
  f.uv[0] = gloss_sphere_uv(d);
  f.uv[1] = f.uv[0];
  f.footprint[0] = gloss_footprint(t, dot(ray, d), gloss_sphere_density(radius, d.y));
  f.footprint[1] = f.footprint[0];
  f.tangent = gloss_sphere_tangent(d);
  f.handedness = 1.0;
  float cos_beta = sqrt(max(0.0, 1.0 - d.y * d.y));
  f.dpdu = 2.0 * pi * radius * cos_beta * f.tangent;
  f.dpdv = pi * radius * cross(d, f.tangent);
  return f;
}
