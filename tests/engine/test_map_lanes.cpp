// The maps' lane forms (engine/trace/map_lanes.h, normal_map_lanes.h) against the contract's
// scalar functions they restate (shading/hit_textures.h read_map and normal_map_normal with the
// horizon rule), lane by lane, over every wrap mode, both lane filters, one- and four-channel
// maps, scaled, turned and moved maps, texel centres, half-texel points, far-off and non-finite
// coordinates, and frames with degenerate tangents and normals facing away.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "engine/trace/map_frame_lanes.h"
#include "engine/trace/map_lanes.h"
#include "engine/trace/normal_map_lanes.h"
#include "engine/trace/sample_packet.h"
#include "shading/hit_textures.h"
#include "shading/map_frame.h"
#include "support/test_maps.h"

namespace gloss {
namespace {

// One map at the lanes of mask: its taps, then its four channels.
void read_map_lanes(const TextureMap& map, MapFilter filter, const float* u, const float* v,
                    const float* log_footprint, std::uint32_t mask, MapTexelLanes& out) {
  MapTaps taps;
  map_taps(map, filter, u, v, log_footprint, mask, taps);
  read_taps(*map.texture, taps, mask, out, 4);
}

// A 37 x 20 map (odd level sizes down to 1 x 1) of values that differ at every texel.
std::shared_ptr<const Texture> odd_map(int channels) {
  return test::texture_of(37, 20, channels, [](int i, int j) {
    return glm::vec4(0.01f * i + 0.3f * std::sin(0.7f * j), 0.02f * j, 0.5f + 0.01f * (i ^ j),
                     0.25f + 0.001f * i * j);
  });
}

TEST(MapLanes, ReadMapLanesGivesReadMapAtEveryLane) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> coordinate(-3.0f, 3.0f), level(-14.0f, 3.0f);
  const float inf = std::numeric_limits<float>::infinity();
  const Wrap wraps[] = {Wrap::repeat, Wrap::clamp, Wrap::mirror};
  int compared = 0;
  for (int channels : {1, 4}) {
    const std::shared_ptr<const Texture> texture = odd_map(channels);
    for (Wrap wu : wraps) {
      for (Wrap wv : wraps) {
        for (MapFilter filter : {MapFilter::trilinear, MapFilter::bilinear}) {
          for (int transform = 0; transform < 3; ++transform) {
            TextureMap map;
            map.texture = texture;
            map.wrap = {wu, wv};
            if (transform >= 1) map.scale = {3.0f, -2.0f};
            if (transform == 2) {
              map.rotation = 30.0f;
              map.offset = {0.25f, -0.5f};
            }
            for (int round = 0; round < 8; ++round) {
              alignas(64) float u[kLanes], v[kLanes], lf[kLanes];
              for (int i = 0; i < kLanes; ++i) {
                u[i] = coordinate(rng);
                v[i] = coordinate(rng);
                lf[i] = level(rng);
              }
              // Texel centres and half-texel points of level 0 and 1 (untransformed maps read
              // them as they are), whole levels, and coordinates far off or not finite.
              u[0] = 3.5f / 37.0f, v[0] = 1.0f - 7.5f / 20.0f, lf[0] = -20.0f;
              u[1] = 4.0f / 37.0f, v[1] = 1.0f - 8.0f / 20.0f, lf[1] = -20.0f;
              u[2] = 2.5f / 18.0f, v[2] = 1.0f - 3.5f / 10.0f,
              lf[2] = -std::log2(37.0f * 20.0f) / 2 + 1;
              u[3] = 1e6f + 0.3f, v[3] = -1e6f;
              u[4] = inf, v[4] = std::nanf("");
              u[5] = 0.0f, v[5] = 1.0f, lf[5] = inf;
              if (round % 2 == 1) {  // one footprint for all lanes
                const float common = level(rng);
                for (float& l : lf) l = common;
              }
              const std::uint32_t mask = round == 0 ? 0xffffu : (rng() & 0xffffu) | 0x3fu;
              MapTexelLanes out;
              for (auto& c : out.texel) {
                for (float& x : c) x = -7.0f;  // what lanes outside the mask must keep
              }
              read_map_lanes(map, filter, u, v, lf, mask, out);
              for (int i = 0; i < kLanes; ++i) {
                if (((mask >> i) & 1u) == 0) {
                  for (int c = 0; c < 4; ++c) ASSERT_EQ(out.texel[c][i], -7.0f);
                  continue;
                }
                const glm::vec4 want =
                    read_map(map, filter, glm::vec2(u[i], v[i]), map_level_of_log(map, lf[i]));
                // Bit for bit: the lanes' taps and blends are read_map's operations in its order.
                for (int c = 0; c < 4; ++c) {
                  ASSERT_EQ(out.texel[c][i], want[c])
                      << "channels " << channels << " wrap " << to_string(wu) << "/"
                      << to_string(wv) << " filter " << to_string(filter) << " transform "
                      << transform << " lane " << i << " uv " << u[i] << "," << v[i] << " lf "
                      << lf[i];
                }
                ++compared;
              }
            }
          }
        }
      }
    }
  }
  EXPECT_GT(compared, 5000);
}

// Half-texel points by hand: between texels (3, 7) and (4, 7) of level 0, the mean of the two.
TEST(MapLanes, AHalfTexelPointIsTheMeanOfItsTwoTexels) {
  TextureMap map;
  map.texture = odd_map(4);
  alignas(64) float u[kLanes] = {}, v[kLanes] = {}, lf[kLanes] = {};
  u[0] = 4.0f / 37.0f;  // x = u W - 0.5 = 3.5
  v[0] = 1.0f - 7.5f / 20.0f;
  lf[0] = -20.0f;
  MapTexelLanes out;
  read_map_lanes(map, MapFilter::trilinear, u, v, lf, 1u, out);
  const std::vector<float>& t = map.texture->levels[0].texels;
  for (int c = 0; c < 4; ++c) {
    const float a = t[(7 * 37 + 3) * 4 + c], b = t[(7 * 37 + 4) * 4 + c];
    EXPECT_NEAR(out.texel[c][0], 0.5f * (a + b), 1e-6f) << "channel " << c;
  }
}

// A read of fewer channels writes those alone (a shininess map reads its first).
TEST(MapLanes, ReadTapsWritesOnlyTheChannelsAsked) {
  TextureMap map;
  map.texture = odd_map(4);
  alignas(64) float u[kLanes], v[kLanes], lf[kLanes];
  for (int i = 0; i < kLanes; ++i) u[i] = 0.05f * i, v[i] = 0.3f, lf[i] = -3.0f;
  MapTaps taps;
  map_taps(map, MapFilter::trilinear, u, v, lf, 0xffffu, taps);
  MapTexelLanes one, four;
  for (auto& c : one.texel) {
    for (float& x : c) x = -7.0f;
  }
  read_taps(*map.texture, taps, 0xffffu, one, 1);
  read_taps(*map.texture, taps, 0xffffu, four, 4);
  for (int i = 0; i < kLanes; ++i) {
    EXPECT_EQ(one.texel[0][i], four.texel[0][i]) << "lane " << i;
    for (int c = 1; c < 4; ++c) EXPECT_EQ(one.texel[c][i], -7.0f) << "lane " << i;
  }
}

glm::vec3 random_unit(std::mt19937& rng) {
  std::normal_distribution<float> g;
  return glm::normalize(glm::vec3(g(rng), g(rng), g(rng)));
}

TEST(MapLanes, NormalMapLanesGiveMapValuesNormal) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  int compared = 0, moved = 0, mirrored = 0;
  for (int variant = 0; variant < 4; ++variant) {
    Material material;
    material.normal_scale = variant == 3 ? 0.0f : 1.5f;
    TextureMap map;
    map.texture = odd_map(4);
    if (variant >= 1) map.rotation = 40.0f;
    if (variant == 2) map.scale = {-1.0f, 2.0f};
    for (int round = 0; round < 64; ++round) {
      SurfaceLanes surfaces;
      TangentLanes frames;
      float texel[4][kLanes];
      MapFrame<float> f[kLanes];
      for (int i = 0; i < kLanes; ++i) {
        // A tangent at random, along n (an axis: Gram-Schmidt then leaves exactly nothing and
        // any_perpendicular chooses, by either of its axes), or zero.
        const int kind = i % 4;
        const glm::vec3 axis =
            i % 8 == 1 ? glm::vec3(0.0f, 0.0f, -1.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
        f[i].n = kind == 1 ? axis : random_unit(rng);
        // The view on n's side, as the renderer's shading normals are (map_values applies the
        // horizon rule only to a normal the map moved, and a flat map moves it by rounding
        // alone: with n facing away that rounding would decide).
        f[i].v = random_unit(rng);
        if (glm::dot(f[i].v, f[i].n) < 0.0f) f[i].v = -f[i].v;
        f[i].tangent = kind == 1 ? 2.0f * f[i].n : kind == 2 ? glm::vec3(0.0f) : random_unit(rng);
        // A random tangent not nearly along n: there Gram-Schmidt loses digits, and the two
        // forms' rounding (FMA contraction differs) grows by 1 / |t - n (n . t)|.
        while (kind != 1 && kind != 2 && std::fabs(glm::dot(f[i].tangent, f[i].n)) > 0.95f) {
          f[i].tangent = random_unit(rng);
        }
        f[i].handedness = unit(rng) < 0.5f ? -1.0f : 1.0f;
        f[i].side = unit(rng) < 0.3f ? -1.0f : 1.0f;
        const bool flat = i == 5, empty = i == 6;  // (0, 0, 1) and a texel of nothing
        for (int c = 0; c < 3; ++c) {
          texel[c][i] = flat ? (c == 2 ? 1.0f : 0.5f) : empty ? 0.5f : unit(rng);
        }
        texel[3][i] = 1.0f;
        surfaces.nx[i] = f[i].n.x, surfaces.ny[i] = f[i].n.y, surfaces.nz[i] = f[i].n.z;
        surfaces.vx[i] = f[i].v.x, surfaces.vy[i] = f[i].v.y, surfaces.vz[i] = f[i].v.z;
        frames.tx[i] = f[i].tangent.x, frames.ty[i] = f[i].tangent.y;
        frames.tz[i] = f[i].tangent.z;
        frames.handedness[i] = f[i].handedness;
        frames.side[i] = f[i].side;
      }
      const std::uint32_t mask = round == 0 ? 0xffffu : rng() & 0xffffu;
      normal_map_lanes(material, map, frames, texel, mask, surfaces);
      for (int i = 0; i < kLanes; ++i) {
        glm::vec3 want = f[i].n;
        if (((mask >> i) & 1u) != 0) {
          const glm::vec3 n0 = f[i].side * f[i].n;
          const glm::vec4 t(texel[0][i], texel[1][i], texel[2][i], texel[3][i]);
          const glm::vec3 n = normal_map_normal(material, map, f[i], n0, t);
          if (n != n0) {
            want = facing_viewer(f[i].side * n, f[i].v);
            ++moved;
            mirrored += glm::dot(f[i].side * n, f[i].v) < 0.0f ? 1 : 0;
          }
          ++compared;
        }
        const glm::vec3 got(surfaces.nx[i], surfaces.ny[i], surfaces.nz[i]);
        for (int c = 0; c < 3; ++c) {
          ASSERT_NEAR(got[c], want[c], 4e-6f) << "variant " << variant << " lane " << i;
        }
      }
    }
  }
  EXPECT_GT(compared, 1500);
  EXPECT_GT(moved, 1000);
  EXPECT_GT(mirrored, 200);
}

// A mesh of n triangles fanned around the origin, with (u, v) (two sets where asked) and its own
// tangents (where asked).
std::shared_ptr<const Mesh> fan(int n, bool two_sets, bool tangents, bool uv = true) {
  auto mesh = std::make_shared<Mesh>();
  std::mt19937 rng(n);
  std::uniform_real_distribution<float> x(-2.0f, 2.0f);
  for (int k = 0; k < n; ++k) {
    const unsigned base = static_cast<unsigned>(mesh->positions.size());
    for (int c = 0; c < 3; ++c) {
      mesh->positions.push_back({x(rng), x(rng), x(rng)});
      if (uv) mesh->uv[0].push_back({x(rng), x(rng)});
      if (uv && two_sets) mesh->uv[1].push_back({x(rng), x(rng)});
      if (tangents) {  // corners of one triangle with either handedness: the first's counts
        mesh->tangents.push_back(glm::vec4(random_unit(rng), (k + c) % 2 == 0 ? 1.0f : -1.0f));
      }
    }
    mesh->triangles.push_back({base, base + 1, base + 2});
  }
  return mesh;
}

TEST(MapLanes, FrameLanesGiveTheMapFramesOfMeshesAndSpheres) {
  Scene scene;
  scene.materials.resize(1);
  for (int k = 0; k < 4; ++k) {
    Object o;
    o.type = ObjectType::mesh;
    o.mesh = fan(5, k == 1, k != 1, k != 3);  // own tangents, two sets, one set, no (u, v)
    scene.objects.push_back(o);
  }
  scene.objects.push_back(sphere_object("ball", glm::vec3(0.5f, -0.25f, 1.0f), 1.5f, 0));
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const float spread = cone_spread(45.0f, 480, 4);
  int compared = 0;
  for (int round = 0; round < 200; ++round) {
    SamplePacket packet(0, 0, kLanes, 1);
    SurfaceLanes surfaces;
    // Runs of lanes on one triangle, as rows of pixels meet them.
    const int object = static_cast<int>(rng() % scene.objects.size());
    for (int i = 0; i < kLanes; ++i) {
      const bool other = i > 0 && unit(rng) < 0.3f;
      packet.object[i] = other ? static_cast<int>(rng() % scene.objects.size()) : object;
      packet.prim[i] = other || i == 0 ? rng() % 5 : packet.prim[i - 1];
      const bool sphere = packet.object[i] == 4;
      if (sphere) packet.prim[i] = 0;
      float b1 = unit(rng), b2 = unit(rng);
      if (b1 + b2 > 1.0f) b1 = 1.0f - b1, b2 = 1.0f - b2;
      packet.u[i] = b1;
      packet.v[i] = b2;
      packet.t[i] = 0.5f + 10.0f * unit(rng);
      const glm::vec3 dir = random_unit(rng);
      packet.dir_x[i] = dir.x, packet.dir_y[i] = dir.y, packet.dir_z[i] = dir.z;
      const glm::vec3 ng = random_unit(rng);
      surfaces.gx[i] = ng.x, surfaces.gy[i] = ng.y, surfaces.gz[i] = ng.z;
      const glm::vec3 p = scene.objects[4].center + 1.5f * random_unit(rng);
      surfaces.px[i] = p.x, surfaces.py[i] = p.y, surfaces.pz[i] = p.z;
    }
    const std::uint32_t mask = round == 0 ? 0xffffu : (rng() & 0xffffu) | 1u;
    MapFrameLanes lanes;
    map_frame_lanes(packet, scene, surfaces, spread, mask, lanes);
    for (int i = 0; i < kLanes; ++i) {
      if (((mask >> i) & 1u) == 0) continue;
      const Object& o = scene.objects[static_cast<std::size_t>(packet.object[i])];
      const glm::vec3 dir(static_cast<float>(packet.dir_x[i]), static_cast<float>(packet.dir_y[i]),
                          static_cast<float>(packet.dir_z[i]));
      const glm::vec3 ng(surfaces.gx[i], surfaces.gy[i], surfaces.gz[i]);
      const glm::vec3 p(surfaces.px[i], surfaces.py[i], surfaces.pz[i]);
      MapFrame<float> f;
      glm::vec3 outward;
      if (o.type == ObjectType::sphere) {
        f = sphere_map_frame(o.center, o.radius, p, packet.t[i], spread, glm::dot(dir, ng));
        outward = p - o.center;
      } else {
        const float b[3] = {1.0f - packet.u[i] - packet.v[i], packet.u[i], packet.v[i]};
        f = mesh_map_frame(*o.mesh, packet.prim[i], b, packet.t[i], spread, glm::dot(dir, ng));
        const glm::uvec3 t = o.mesh->triangles[packet.prim[i]];
        outward = glm::cross(o.mesh->positions[t.y] - o.mesh->positions[t.x],
                             o.mesh->positions[t.z] - o.mesh->positions[t.x]);
      }
      const std::string where = "object " + std::to_string(packet.object[i]) + " lane " +
                                std::to_string(i) + " round " + std::to_string(round);
      for (int set = 0; set < 2; ++set) {
        ASSERT_NEAR(lanes.u[set][i], f.uv[set].x, 1e-6f) << where;
        ASSERT_NEAR(lanes.v[set][i], f.uv[set].y, 1e-6f) << where;
        const float want = std::log2(f.footprint[set]);
        if (std::isinf(want)) {
          ASSERT_EQ(lanes.log_footprint[set][i], want) << where;
        } else {  // libmvec's log2f: within a few float ulp of log2f
          ASSERT_NEAR(lanes.log_footprint[set][i], want, 1e-5f) << where;
        }
      }
      ASSERT_NEAR(lanes.tangents.tx[i], f.tangent.x, 1e-5f) << where;
      ASSERT_NEAR(lanes.tangents.ty[i], f.tangent.y, 1e-5f) << where;
      ASSERT_NEAR(lanes.tangents.tz[i], f.tangent.z, 1e-5f) << where;
      ASSERT_EQ(lanes.tangents.handedness[i], f.handedness) << where;
      ASSERT_EQ(lanes.tangents.side[i], glm::dot(outward, ng) < 0.0f ? -1.0f : 1.0f) << where;
      ++compared;
    }
  }
  EXPECT_GT(compared, 1500);
}

}  // namespace
}  // namespace gloss
