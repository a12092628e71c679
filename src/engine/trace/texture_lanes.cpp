#include "engine/trace/texture_lanes.h"

#include <array>
#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>

#include "engine/adaptive/refined_samples.h"
#include "engine/trace/map_frame_lanes.h"
#include "engine/trace/map_lanes.h"
#include "engine/trace/normal_map_lanes.h"
#include "engine/trace/sample_packet.h"

#include "shading/hit_textures.h"
#include "shading/map_frame.h"
#include "texture/footprint.h"

namespace gloss {

namespace {
// The side a hit's surface was modelled facing: a sphere's outward direction, a triangle's
// winding (its face normal before the two-sided rule).
glm::vec3 outward(const Object& object, std::uint32_t prim, const glm::vec3& p) {
  if (object.type == ObjectType::sphere) return p - object.center;
  const Mesh& mesh = *object.mesh;
  const glm::uvec3 t = mesh.triangles[prim];
  return glm::cross(mesh.positions[t.y] - mesh.positions[t.x],
                    mesh.positions[t.z] - mesh.positions[t.x]);
}

// The hit's MapFrame (shading/map_frame.h) with the lane's shading normal, view and side.
MapFrame<float> lane_frame(const SamplePacket& packet, const Object& object,
                           const SurfaceLanes& surfaces, float spread, int i) {
  const glm::vec3 dir(static_cast<float>(packet.dir_x[i]), static_cast<float>(packet.dir_y[i]),
                      static_cast<float>(packet.dir_z[i]));
  const Surface s = surfaces.get(i);
  const float t = packet.t[i];
  const float cos_theta = glm::dot(dir, s.ng);
  MapFrame<float> frame;
  if (object.type == ObjectType::sphere) {
    frame = sphere_map_frame(object.center, object.radius, s.p, t, spread, cos_theta);
  } else {
    const float b[3] = {1.0f - packet.u[i] - packet.v[i], packet.u[i], packet.v[i]};
    frame = mesh_map_frame(*object.mesh, packet.prim[i], b, t, spread, cos_theta);
  }
  frame.n = s.n;
  frame.v = s.v;
  // The two-sided rule turned n_g towards the viewer where the ray met the back: for a
  // triangle the stored face orientation tells, for a sphere the outward direction.
  frame.side = glm::dot(outward(object, packet.prim[i], s.p), s.ng) < 0.0f ? -1.0f : 1.0f;
  return frame;
}

// Where the plan's channels are (-1: not planned).
struct TexelChannels {
  int kd, ka, ks, ke, alpha;
  explicit TexelChannels(const TexturePlan& plan)
      : kd(plan.kd_channel()),
        ka(plan.ka_channel()),
        ks(plan.ks_channel()),
        ke(plan.ke_channel()),
        alpha(plan.alpha_channel()) {}
};

void put3(TexelLanes& out, int channel, int i, const glm::vec3& value) {
  for (int c = 0; c < 3; ++c) out.channel[channel + c][i] = value[c];
}

// Lane i through map_values, as the reference path does (bump maps, the nearest-texel knob).
void scalar_lane(const Material& material, const MapFrame<float>& frame, const TexturePlan& plan,
                 const TexelChannels& ch, int i, SurfaceLanes& surfaces, TexelLanes& out) {
  const MapValues<float> values = map_values(material, frame, plan.filter);
  if (ch.kd >= 0) put3(out, ch.kd, i, values.kd);
  if (ch.ka >= 0 && ch.ka != ch.kd) put3(out, ch.ka, i, values.ka);
  if (ch.ks >= 0) put3(out, ch.ks, i, values.ks);
  if (ch.ke >= 0) put3(out, ch.ke, i, values.ke);
  if (ch.alpha >= 0) out.channel[ch.alpha][i] = values.alpha;
  if (plan.normals) {
    surfaces.nx[i] = values.n.x;
    surfaces.ny[i] = values.n.y;
    surfaces.nz[i] = values.n.z;
  }
}

// The lanes of mask (one material, no bump map, a lane filter) through map_taps and read_taps: the
// values map_values gives them.
void material_lanes(const Material& material, const MapFrameLanes& frames, std::uint32_t mask,
                    const TexturePlan& plan, const TexelChannels& ch, SurfaceLanes& surfaces,
                    TexelLanes& out) {
  const std::array<TextureMap, kMapSlots>& maps = *material.map_storage;
  MapTexelLanes texels{};  // lanes outside the mask are read (and discarded) by vector loops
  MapTaps taps;
  const TextureMap* tapped = nullptr;  // the map taps were last made for
  // channels: what the slot uses (a shininess map its first; colour and normal maps three);
  // the channels after them keep the previous map's values, so each use below reads only what
  // its own read filled.
  auto read = [&](MapSlot slot, int channels = 3) -> const TextureMap* {
    const TextureMap& map = maps[static_cast<int>(slot)];
    if (!map.present()) return nullptr;
    if (tapped == nullptr || !same_taps(*tapped, map)) {
      const int set = map.uv_set == 1 ? 1 : 0;
      map_taps(map, plan.filter, frames.u[set], frames.v[set], frames.log_footprint[set], mask,
               taps);
      tapped = &map;
    }
    read_taps(*map.texture, taps, mask, texels, channels);
    return &map;
  };
  auto each_lane = [mask](auto&& f) {
    for (std::uint32_t rest = mask; rest != 0; rest &= rest - 1) f(__builtin_ctz(rest));
  };
  auto rgb = [&texels](int i) {
    return glm::vec3(texels.texel[0][i], texels.texel[1][i], texels.texel[2][i]);
  };
  if (read(MapSlot::diffuse) != nullptr) {
    each_lane([&](int i) {
      if (ch.kd >= 0) put3(out, ch.kd, i, rgb(i));
      if (ch.ka >= 0 && ch.ka != ch.kd) put3(out, ch.ka, i, rgb(i));
    });
  }
  if (read(MapSlot::ambient) != nullptr && ch.ka >= 0 && ch.ka != ch.kd) {
    each_lane([&](int i) { put3(out, ch.ka, i, rgb(i)); });
  }
  if (read(MapSlot::specular) != nullptr && ch.ks >= 0) {
    each_lane([&](int i) { put3(out, ch.ks, i, rgb(i)); });
  }
  if (read(MapSlot::emission) != nullptr && ch.ke >= 0) {
    each_lane([&](int i) { put3(out, ch.ke, i, rgb(i)); });
  }
  if (read(MapSlot::shininess, 1) != nullptr && ch.alpha >= 0) {
    each_lane([&](int i) { out.channel[ch.alpha][i] = texels.texel[0][i]; });
  }
  if (const TextureMap* map = read(MapSlot::normal)) {
    normal_map_lanes(material, *map, frames.tangents, texels.texel, mask, surfaces);
  }
}

}  // namespace

void unit_texels(std::size_t channels, TexelLanes& out) {
  for (std::size_t c = 0; c < channels; ++c) {
    for (int i = 0; i < kLanes; ++i) out.channel[c][i] = 1.0f;
  }
}

void texture_lanes(const SamplePacket& packet, const SampleCache& cache, const RenderContext& ctx,
                   int spp, SurfaceLanes& surfaces, TexelLanes& out) {
  const TexturePlan& plan = ctx.plan.textures;
  unit_texels(plan.channels(), out);
  const Scene& scene = *ctx.scene;
  const float spread = cone_spread(static_cast<float>(scene.camera.fov_y), cache.image_height, spp);
  const TexelChannels ch(plan);
  // Lanes of textured materials: their frames, then the maps of each material in the packet for
  // all its lanes at once (map_lanes.h), or per lane where a map needs map_values.
  alignas(64) std::int32_t material_of[kLanes];
  std::uint32_t pending = 0;
  std::int32_t last = -1;  // the lanes of a packet mostly share a material: its flags once
  bool textured = false, per_lane = false;
  for (int i = 0; i < kLanes; ++i) {
    material_of[i] = -1;
    if (packet.object[i] < 0 || packet.valid[i] == 0) continue;
    const Object& object = scene.objects[static_cast<std::size_t>(packet.object[i])];
    const Material& material = scene.materials[static_cast<std::size_t>(object.material)];
    if (object.material != last) {
      last = object.material;
      textured = material.textured();
      per_lane = !lane_filter(plan.filter) || material.map(MapSlot::bump).present();
    }
    if (!textured) continue;
    if (per_lane) {
      scalar_lane(material, lane_frame(packet, object, surfaces, spread, i), plan, ch, i, surfaces,
                  out);
      continue;
    }
    material_of[i] = object.material;
    pending |= 1u << i;
  }
  if (pending == 0) return;
  MapFrameLanes frames;
  map_frame_lanes(packet, scene, surfaces, spread, pending, frames);
  while (pending != 0) {
    const std::int32_t m = material_of[__builtin_ctz(pending)];
    std::uint32_t group = 0;
    for (int i = 0; i < kLanes; ++i) group |= (material_of[i] == m ? 1u : 0u) << i;
    pending &= ~group;
    material_lanes(scene.materials[static_cast<std::size_t>(m)], frames, group, plan, ch, surfaces,
                   out);
  }
}

void mapped_surfaces(const SamplePacket& packet, const SampleCache& cache, const RenderContext& ctx,
                     const SamplePlane& plane, SurfaceLanes& surfaces) {
  packet_surfaces(packet, cache, ctx, surfaces);
  if (!ctx.plan.textures.normals) return;
  TexelLanes scratch;
  texture_lanes(packet, cache, ctx, plane_spp(cache, plane), surfaces, scratch);
}

bool resample_textures(SampleCache& cache, const RenderContext& ctx) {
  const std::size_t channels = ctx.plan.textures.channels();
  if (channels == 0) return true;
  auto visit = [&](SamplePacket& packet, SamplePlane& plane) -> long long {
    TexelLanes texels;
    if (!any_hit(packet)) {
      unit_texels(channels, texels);
    } else {
      SurfaceLanes surfaces;
      packet_surfaces(packet, cache, ctx, surfaces);
      texture_lanes(packet, cache, ctx, plane_spp(cache, plane), surfaces, texels);
    }
    store_texels(packet, cache.width, texels, plane);
    return 0;
  };
  SamplePlane& refined = cache.refined.plane;
  return visit_cached_samples(cache, ctx, visit) &&
         visit_refined_samples(cache, ctx,
                               [&](SamplePacket& packet) { return visit(packet, refined); });
}

void store_texels(const SamplePacket& packet, int width, const TexelLanes& lanes,
                  SamplePlane& plane) {
  for (std::size_t c = 0; c < plane.texels.size(); ++c) {
    stream_lanes(packet, width, lanes.channel[c], plane.texels[c].data());
  }
}

void load_texels(const SamplePacket& packet, int width, const SamplePlane& plane,
                 TexelLanes& lanes) {
  for (std::size_t c = 0; c < plane.texels.size(); ++c) {
    load_lanes(packet, width, plane.texels[c].data(), lanes.channel[c], 1.0f);
  }
}

}  // namespace gloss
