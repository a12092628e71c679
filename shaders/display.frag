#version 330 core
// The viewport's display transform (docs/spec/shading.md, "Output encodings"), the GLSL twin of
// src/display/display_transform.h: linear RGB times the exposure gain, the tone curve (none,
// Reinhard, ACES fit), clamped to [0, 1], then written as is (the classic look) or sRGB-encoded.
// Modes: 0 shows u_a; 1 shows u_a + u_b (emissive + ambient); 2 shows the largest per-channel
// |u_a - u_b| on the heat ramp, where u_heat_scale (linear units) maps to the ramp's top.
// With u_clip_overlay, modes 0 and 1 show pixels with any channel above 1 before the clamp (what
// the clamp cuts; editor/model/measure/exposure_histogram.h counts the same) as magenta and dark
// zebra stripes.
in vec2 v_uv;
out vec4 frag_colour;

uniform sampler2D u_a;
uniform sampler2D u_b;
uniform int u_mode;
uniform float u_gain;         // 2^exposure, exposure in stops
uniform int u_tone;           // 0 none, 1 Reinhard, 2 ACES (ToneCurve's order)
uniform bool u_srgb;
uniform float u_heat_scale;   // > 0
uniform vec3 u_heat_ramp[5];  // display colours at t = 0, 1/4, 1/2, 3/4, 1
uniform bool u_clip_overlay;

vec3 encode_srgb(vec3 c) {
  vec3 curve = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
  return mix(c * 12.92, curve, step(vec3(0.0031308), c));
}

// Exposed values are held below 1e18 first: the curves stay finite and +Inf shows as 1.
vec3 tone_curve(vec3 x) {
  if (u_tone == 1) return x / (1.0 + x);
  if (u_tone == 2) return x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14);
  return x;
}

vec3 heat(float t) {
  float x = clamp(t, 0.0, 1.0) * 4.0;
  int i = min(int(floor(x)), 3);
  return mix(u_heat_ramp[i], u_heat_ramp[i + 1], x - float(i));
}

void main() {
  vec3 a = texture(u_a, v_uv).rgb;
  if (u_mode == 2) {
    vec3 d = abs(a - texture(u_b, v_uv).rgb);
    frag_colour = vec4(heat(max(d.r, max(d.g, d.b)) / u_heat_scale), 1.0);
    return;
  }
  if (u_mode == 1) a += texture(u_b, v_uv).rgb;
  vec3 e = a * u_gain;
  // Not above 0 (negatives, NaN) shows as 0, as the clamp would leave it.
  e = vec3(e.r > 0.0 ? min(e.r, 1e18) : 0.0, e.g > 0.0 ? min(e.g, 1e18) : 0.0,
           e.b > 0.0 ? min(e.b, 1e18) : 0.0);
  vec3 toned = tone_curve(e);
  if (u_clip_overlay && max(toned.r, max(toned.g, toned.b)) > 1.0) {
    // 4-pixel diagonal stripes: no image colour looks like them.
    bool light = mod(floor((gl_FragCoord.x + gl_FragCoord.y) / 4.0), 2.0) < 1.0;
    frag_colour = vec4(light ? vec3(1.0, 0.0, 1.0) : vec3(0.15, 0.0, 0.15), 1.0);
    return;
  }
  vec3 c = min(toned, vec3(1.0));
  if (u_srgb) c = encode_srgb(c);
  frag_colour = vec4(c, 1.0);
}
