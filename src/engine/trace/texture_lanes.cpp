#include "engine/trace/texture_lanes.h"

#include "engine/trace/refined_samples.h"
#include "engine/trace/sample_packet.h"

#include <glm/geometric.hpp>

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
}  // namespace

void unit_texels(std::size_t channels, TexelLanes& out) {
  for (std::size_t c = 0; c < channels; ++c) {
    for (int i = 0; i < kLanes; ++i) out.channel[c][i] = 1.0f;
  }
}

void texture_lanes(const SamplePacket& packet, const SampleCache& cache, const RenderContext& ctx,
                   int spp, SurfaceLanes& surfaces, TexelLanes& out) {
  const TexturePlan& plan = ctx.plan.textures;
  const std::size_t channels = plan.channels();
  unit_texels(channels, out);
  const Scene& scene = *ctx.scene;
  const float spread = cone_spread(static_cast<float>(scene.camera.fov_y), cache.image_height, spp);
  const int kd = plan.kd_channel(), ka = plan.ka_channel(), ks = plan.ks_channel(),
            ke = plan.ke_channel(), alpha = plan.alpha_channel();
  for (int i = 0; i < kLanes; ++i) {
    if (packet.object[i] < 0 || packet.valid[i] == 0) continue;
    const Object& object = scene.objects[static_cast<std::size_t>(packet.object[i])];
    const Material& material = scene.materials[static_cast<std::size_t>(object.material)];
    if (!material.textured()) continue;
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
    const MapValues<float> values = map_values(material, frame, plan.filter);
    if (kd >= 0) {
      for (int c = 0; c < 3; ++c) out.channel[kd + c][i] = values.kd[c];
    }
    if (ka >= 0 && ka != kd) {
      for (int c = 0; c < 3; ++c) out.channel[ka + c][i] = values.ka[c];
    }
    if (ks >= 0) {
      for (int c = 0; c < 3; ++c) out.channel[ks + c][i] = values.ks[c];
    }
    if (ke >= 0) {
      for (int c = 0; c < 3; ++c) out.channel[ke + c][i] = values.ke[c];
    }
    if (alpha >= 0) out.channel[alpha][i] = values.alpha;
    if (plan.normals) {
      surfaces.nx[i] = values.n.x;
      surfaces.ny[i] = values.n.y;
      surfaces.nz[i] = values.n.z;
    }
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
