#include "engine/trace/embree_scene.h"

#include <cstring>
#include <mutex>
#include <string>

#include "base/error.h"
#include "engine/trace/self_shadow.h"

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

void attach_sphere(RTCDevice device, RTCScene scene, const Object& object, unsigned id) {
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0,
                                                        RTC_FORMAT_FLOAT4, 4 * sizeof(float), 1));
  v[0] = object.center.x;
  v[1] = object.center.y;
  v[2] = object.center.z;
  v[3] = object.radius;
  rtcSetGeometryOccludedFilterFunction(geom, drop_origin_sphere_hits);
  rtcCommitGeometry(geom);
  rtcAttachGeometryByID(scene, geom, id);
  rtcReleaseGeometry(geom);
}

void attach_mesh(RTCDevice device, RTCScene scene, const Mesh& mesh, unsigned id) {
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0,
                                                        RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                        mesh.positions.size()));
  std::memcpy(v, mesh.positions.data(), mesh.positions.size() * 3 * sizeof(float));
  auto* t = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0,
                                                           RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
                                                           mesh.triangles.size()));
  std::memcpy(t, mesh.triangles.data(), mesh.triangles.size() * 3 * sizeof(unsigned));
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
    if (object.type == ObjectType::sphere) {
      attach_sphere(m_device, m_scene, object, id);
    } else if (object.mesh && !object.mesh->triangles.empty()) {
      attach_mesh(m_device, m_scene, *object.mesh, id);
    }
  }
  rtcCommitScene(m_scene);
  check(m_device, "scene build");
}

EmbreeScene::~EmbreeScene() {
  if (m_scene != nullptr) rtcReleaseScene(m_scene);
}

}  // namespace gloss
