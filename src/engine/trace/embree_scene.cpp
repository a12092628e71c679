#include "engine/trace/embree_scene.h"

#include <cstring>
#include <mutex>
#include <string>

#include "base/error.h"
#include "engine/trace/cut_outs.h"
#include "engine/trace/self_shadow.h"
#include "shading/hit_textures.h"

namespace gloss {

namespace {
void on_embree_error(void*, RTCError code, const char* message) {
  // Errors surface through rtcGetDeviceError in build(); nothing to do here but keep Embree
  // from printing on its own.
  (void)code;
  (void)message;
}

void check(RTCDevice device, const char* what) {
  const RTCError err = rtcGetDeviceError(device);
  if (err != RTC_ERROR_NONE) {
    throw RuntimeFailure(std::string("Embree error ") + std::to_string(static_cast<int>(err)) +
                         " during " + what);
  }
}

void attach_sphere(RTCDevice device, RTCScene scene, const Object& object, unsigned id,
                   const CutOut* cut) {
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0,
                                                        RTC_FORMAT_FLOAT4, 4 * sizeof(float), 1));
  v[0] = object.center.x;
  v[1] = object.center.y;
  v[2] = object.center.z;
  v[3] = object.radius;
  rtcSetGeometryOccludedFilterFunction(geom, drop_origin_sphere_hits);
  if (cut != nullptr) {
    rtcSetGeometryUserData(geom, const_cast<CutOut*>(cut));
    rtcSetGeometryIntersectFilterFunction(geom, cut_out_sphere);
    rtcSetGeometryOccludedFilterFunction(geom, cut_out_sphere_occluded);
  }
  rtcCommitGeometry(geom);
  rtcAttachGeometryByID(scene, geom, id);
  rtcReleaseGeometry(geom);
}

void attach_mesh(RTCDevice device, RTCScene scene, const Mesh& mesh, unsigned id,
                 const CutOut* cut) {
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0,
                                                        RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                        mesh.positions.size()));
  std::memcpy(v, mesh.positions.data(), mesh.positions.size() * 3 * sizeof(float));
  auto* t = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0,
                                                           RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
                                                           mesh.triangles.size()));
  std::memcpy(t, mesh.triangles.data(), mesh.triangles.size() * 3 * sizeof(unsigned));
  if (cut != nullptr) {
    rtcSetGeometryUserData(geom, const_cast<CutOut*>(cut));
    rtcSetGeometryIntersectFilterFunction(geom, cut_out_triangles);
    rtcSetGeometryOccludedFilterFunction(geom, cut_out_triangles);
  }
  rtcCommitGeometry(geom);
  rtcAttachGeometryByID(scene, geom, id);
  rtcReleaseGeometry(geom);
}
}  // namespace

RTCDevice embree_device() {
  static std::once_flag once;
  static RTCDevice device = nullptr;
  std::call_once(once, [] {
    device = rtcNewDevice(nullptr);
    if (device == nullptr) throw RuntimeFailure("cannot create the Embree device");
    rtcSetDeviceErrorFunction(device, on_embree_error, nullptr);
  });
  return device;
}

EmbreeScene::EmbreeScene(const Scene& scene)
    : m_device(embree_device()), m_surfaces(make_surface_table(scene)) {
  m_scene = rtcNewScene(m_device);
  rtcSetSceneFlags(m_scene, RTC_SCENE_FLAG_NONE);
  rtcSetSceneBuildQuality(m_scene, RTC_BUILD_QUALITY_HIGH);
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const Object& object = scene.objects[i];
    const auto id = static_cast<unsigned>(i);
    if (object.hidden) continue;  // no ray meets it: not seen, no shadow, not picked
    std::unique_ptr<CutOut> cut = make_cut_out(scene, object);
    // A mesh without (u, v) reads the map's texel at (0, 0): cut out whole, or not at all.
    if (cut != nullptr && object.type != ObjectType::sphere && object.mesh &&
        !object.mesh->textured()) {
      const bool opaque = opaque_at(cut->map, glm::vec2(0.0f));
      cut.reset();
      if (!opaque) continue;
    }
    if (object.type == ObjectType::sphere) {
      attach_sphere(m_device, m_scene, object, id, cut.get());
    } else if (object.mesh && !object.mesh->triangles.empty()) {
      attach_mesh(m_device, m_scene, *object.mesh, id, cut.get());
    }
    if (cut != nullptr) m_cut_outs.push_back(std::move(cut));
  }
  rtcCommitScene(m_scene);
  check(m_device, "scene build");
}

EmbreeScene::~EmbreeScene() {
  if (m_scene != nullptr) rtcReleaseScene(m_scene);
}

}  // namespace gloss
