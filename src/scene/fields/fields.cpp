#include "scene/fields/fields.h"

#include "scene/limits.h"

namespace gloss {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

const FieldTable<Material>& material_fields() {
  static const FieldTable<Material> table = [] {
    constexpr FieldKind colour = FieldKind::colour;
    FieldTable<Material> t;
    t.push_back(vec3_field<&Material::ambient>(colour, "ambient", "ka ambient")
                    .invalidates(ChangeClass::shade)
                    .explain("ka: reflects the ambient light A_scene + sum of La"));
    t.push_back(vec3_field<&Material::diffuse>(colour, "diffuse", "kd diffuse")
                    .invalidates(ChangeClass::shade)
                    .explain("kd: the Lambert term, kd Ld max(N.L, 0)"));
    t.push_back(vec3_field<&Material::specular>(colour, "specular", "ks specular")
                    .invalidates(ChangeClass::shade)
                    .explain("ks: the highlight, ks Ls c^alpha"));
    t.push_back(vec3_field<&Material::emission>(colour, "emission", "ke emission")
                    .invalidates(ChangeClass::shade)
                    .explain("ke: light of its own, unaffected by any light"));
    // The contract's numerical promises hold for alpha in [0, 1e6]; the slider offers 0..1e4.
    t.push_back(scalar_field<&Material::shininess>(FieldKind::number, "shininess", "shininess")
                    .range(0.0, 1e6)
                    .ui(0.0, 1e4, true)
                    .invalidates(ChangeClass::exponent)
                    .explain("the exponent alpha of c^alpha: larger is a smaller, sharper "
                             "highlight"));
    // Maps (docs/spec/shading.md, "Textures"): a colour or shininess map is sampled again at the
    // cached hits; an opacity map changes what rays hit; a normal or bump map moves the shading
    // normal, so the light factors are made again.
    using M = Material;
    t.push_back(map_field<M, MapSlot::diffuse>("diffuse_map", "diffuse map")
                    .invalidates(ChangeClass::texture)
                    .explain("kd times the map, per channel (and ka, unless an ambient map is "
                             "given); sRGB-decoded unless the file says linear"));
    t.push_back(map_field<M, MapSlot::ambient>("ambient_map", "ambient map")
                    .invalidates(ChangeClass::texture)
                    .explain("ka times the map, per channel (for example an occlusion map)"));
    t.push_back(map_field<M, MapSlot::specular>("specular_map", "specular map")
                    .invalidates(ChangeClass::texture)
                    .explain("ks times the map, per channel"));
    t.push_back(map_field<M, MapSlot::emission>("emission_map", "emission map")
                    .invalidates(ChangeClass::texture)
                    .explain("ke times the map, per channel"));
    t.push_back(map_field<M, MapSlot::shininess>("shininess_map", "shininess map")
                    .invalidates(ChangeClass::texture)
                    .explain("alpha times the map's first channel (linear data)"));
    t.push_back(map_field<M, MapSlot::opacity>("opacity_map", "opacity map")
                    .invalidates(ChangeClass::full)
                    .explain("a cut-out: no surface where the map (its alpha, else its first "
                             "channel) is below 0.5"));
    t.push_back(map_field<M, MapSlot::normal>("normal_map", "normal map")
                    .invalidates(ChangeClass::light)
                    .explain("tangent-space normals, +Y up (glTF, OpenGL): n = 2 c - 1"));
    t.push_back(
        scalar_field<&Material::normal_scale>(FieldKind::number, "normal_scale", "normal scale")
            .range(-1e3, 1e3)
            .ui(0.0, 2.0)
            .invalidates(ChangeClass::light)
            .only_when([](const Material& m) { return m.map(MapSlot::normal).named(); })
            .explain("the normal map's x and y times this: 0 is flat, 1 as painted"));
    t.push_back(map_field<M, MapSlot::bump>("bump_map", "bump map")
                    .invalidates(ChangeClass::light)
                    .explain("a height field (first channel, linear) that tilts the shading "
                             "normal"));
    t.push_back(scalar_field<&Material::bump_scale>(FieldKind::number, "bump_scale", "bump scale")
                    .range(-1e6, 1e6)
                    .ui(0.0, 0.1)
                    .invalidates(ChangeClass::light)
                    .only_when([](const Material& m) { return m.map(MapSlot::bump).named(); })
                    .explain("the bump map's height times this, scene units"));
    return t;
  }();
  return table;
}

const FieldTable<PhysicalReference>& reference_fields() {
  static const FieldTable<PhysicalReference> table = [] {
    std::vector<const char*> kinds;
    for (int i = 0; i < kReferenceKinds; ++i) kinds.push_back(to_string(ReferenceKind(i)));
    // The Phong renderer never reads a reference: an edit invalidates none of its work (the
    // editor's reference view compares documents itself).
    FieldTable<PhysicalReference> t;
    t.push_back(choice_field<&PhysicalReference::kind>("kind", "reference", kinds)
                    .invalidates(ChangeClass::none)
                    .needed()
                    .explain("a measured metal (F0 from Real-Time Rendering, 4th ed., Table 9.2) "
                             "or a dielectric (F0 0.04 plus a base colour)"));
    t.push_back(vec3_field<&PhysicalReference::base>(FieldKind::colour, "base", "base colour")
                    .range(0.0, 1.0)
                    .invalidates(ChangeClass::none)
                    .explain("dielectric: the diffuse albedo under the 4% Fresnel coat, linear "
                             "RGB 0..1 (kept, unused, for metals)"));
    t.push_back(
        scalar_field<&PhysicalReference::roughness>(FieldKind::number, "roughness", "roughness")
            .range(0.0, 1.0)
            .open(true, false)
            .ui(0.01, 1.0)
            .invalidates(ChangeClass::none)
            .explain("perceptual roughness; GGX width a = roughness^2 (0 < r <= 1)"));
    return t;
  }();
  return table;
}

namespace {
bool positioned(const Light& l) {
  return has_position(l.type);
}
bool aimed(const Light& l) {
  return l.type != LightType::point;
}
bool spot(const Light& l) {
  return l.type == LightType::spot;
}
bool directional(const Light& l) {
  return l.type == LightType::directional;
}
}  // namespace

const FieldTable<Light>& light_fields() {
  static const FieldTable<Light> table = [] {
    constexpr FieldKind colour = FieldKind::colour, vector = FieldKind::vector;
    FieldTable<Light> t;
    // First: whether the other fields apply is judged on it (read_fields reads in table order).
    t.push_back(choice_field<&Light::type>("type", "type", {"point", "directional", "spot"})
                    .invalidates(ChangeClass::light)
                    .explain("point: from a position; directional: from a direction, no "
                             "attenuation; spot: a point light cut to a cone"));
    t.push_back(vec3_field<&Light::position>(vector, "position", "position")
                    .range(-kMaxCoordinate, kMaxCoordinate)
                    .ui(-1e4, 1e4)
                    .invalidates(ChangeClass::light)
                    .needed()
                    .only_when(positioned)
                    .explain("P, world units"));
    t.push_back(vec3_field<&Light::direction>(vector, "direction", "direction")
                    .range(-kMaxCoordinate, kMaxCoordinate)
                    .ui(-1.0, 1.0)
                    .invalidates(ChangeClass::light)
                    .only_when(aimed)
                    .explain("D, the way the light travels (any length but 0); camera space "
                             "(x right, y up, -z ahead) when it follows the camera"));
    t.push_back(vec3_field<&Light::ambient>(colour, "ambient", "La ambient")
                    .invalidates(ChangeClass::shade)
                    .explain("La: added to the ambient sum, never shadowed or attenuated"));
    t.push_back(vec3_field<&Light::diffuse>(colour, "diffuse", "Ld diffuse")
                    .invalidates(ChangeClass::shade)
                    .explain("Ld: the colour the diffuse term sees"));
    t.push_back(vec3_field<&Light::specular>(colour, "specular", "Ls specular")
                    .invalidates(ChangeClass::shade)
                    .explain("Ls: the colour the highlight sees"));
    t.push_back(vec3_field<&Light::attenuation>(vector, "attenuation", "attenuation")
                    .range(0.0, kInf)
                    .ui(0.0, 100.0)
                    .invalidates(ChangeClass::light)
                    .only_when(positioned)
                    .explain("c0, c1, c2: 1 / (c0 + c1 d + c2 d^2), not all 0"));
    t.push_back(scalar_field<&Light::cutoff>(FieldKind::number, "cutoff", "cutoff")
                    .range(0.0, 90.0)
                    .open(true, false)
                    .ui(0.01, 90.0)
                    .invalidates(ChangeClass::light)
                    .only_when(spot)
                    .explain("the cone's half-angle, degrees: no light outside it"));
    t.push_back(scalar_field<&Light::inner>(FieldKind::number, "inner", "inner")
                    .range(0.0, 90.0)
                    .ui(0.0, 90.0)
                    .invalidates(ChangeClass::light)
                    .only_when(spot)
                    .explain("half-angle of full strength, degrees, used as min(inner, cutoff); "
                             "the edge fades between them (at cutoff or above: a hard edge)"));
    t.push_back(scalar_field<&Light::exponent>(FieldKind::number, "exponent", "exponent")
                    .range(0.0, 1e6)
                    .ui(0.0, 1e3, true)
                    .invalidates(ChangeClass::light)
                    .only_when(spot)
                    .explain("fall-off towards the edge: cos_t^exponent (OpenGL's "
                             "GL_SPOT_EXPONENT)"));
    t.push_back(
        scalar_field<&Light::follow_camera>(FieldKind::flag, "follow_camera", "follow camera")
            .invalidates(ChangeClass::light)
            .only_when(directional)
            .explain("a headlight: the direction is in camera space and turns with "
                     "the camera"));
    return t;
  }();
  return table;
}

const char* to_string(LightType type) {
  return light_fields().front().choices.at(static_cast<std::size_t>(type));
}

const FieldTable<RenderSettings>& render_fields() {
  static const FieldTable<RenderSettings> table = [] {
    constexpr FieldKind whole = FieldKind::whole, flag = FieldKind::flag;
    FieldTable<RenderSettings> t;
    t.push_back(scalar_field<&RenderSettings::width>(whole, "width", "width")
                    .range(1, kMaxImageSide)
                    .ui(1, 4096)
                    .explain("image width, pixels"));
    t.push_back(scalar_field<&RenderSettings::height>(whole, "height", "height")
                    .range(1, kMaxImageSide)
                    .ui(1, 4096)
                    .explain("image height, pixels"));
    t.push_back(scalar_field<&RenderSettings::spp>(whole, "spp", "samples per pixel")
                    .range(1, kMaxSpp)
                    .ui(1, 256, true)
                    .explain("samples per pixel, stratified; 1 samples the pixel centre"));
    t.push_back(
        choice_field<&RenderSettings::model>("model", "shading model", {"phong", "blinn-phong"})
            .invalidates(ChangeClass::exponent)
            .explain("phong: c = R.V; blinn-phong: c = N.H"));
    t.push_back(scalar_field<&RenderSettings::shadows>(flag, "shadows", "shadows")
                    .invalidates(ChangeClass::light)
                    .explain("shadow rays towards every light"));
    t.push_back(
        scalar_field<&RenderSettings::energy_normalize>(flag, "energy_normalize",
                                                        "energy normalisation")
            .invalidates(ChangeClass::shade)
            .explain("specular x (alpha + 2) / 2pi for Phong, (alpha + 8) / 8pi for Blinn-Phong"));
    // The display encoding changes no linear value: nothing to re-render.
    t.push_back(scalar_field<&RenderSettings::srgb>(flag, "srgb", "sRGB encoding")
                    .invalidates(ChangeClass::none)
                    .explain("PNGs and the viewport sRGB-encoded; off: clamped as is"));
    // The display transform changes no linear value (PFM and EXR hold the image before it);
    // adaptive sampling's placement reads the displayed image, which the engine's follow-up
    // after every edit chooses again (engine/adaptive/adaptive_refinement.h).
    t.push_back(
        scalar_field<&RenderSettings::exposure>(FieldKind::number, "exposure", "exposure")
            .range(-kMaxExposureStops, kMaxExposureStops)
            .ui(-8.0, 8.0)
            .invalidates(ChangeClass::none)
            .explain("stops: displayed value = linear x 2^exposure, before the tone curve"));
    t.push_back(
        choice_field<&RenderSettings::tone>("tone", "tone curve", {"none", "reinhard", "aces"})
            .invalidates(ChangeClass::none)
            .explain("after the exposure, before the clamp: none (classic), Reinhard "
                     "x / (1 + x), or the ACES film fit (Narkowicz)"));
    t.push_back(scalar_field<&RenderSettings::seed>(whole, "seed", "seed")
                    .range(0, 4294967295.0)
                    .ui(0, 1000)
                    .explain("jitter seed for more than one sample; same seed, same image"));
    t.push_back(choice_field<&RenderSettings::pow>("pow", "pow", {"exact", "fast"})
                    .invalidates(ChangeClass::exponent)
                    .explain("c^alpha exactly, or by a fast approximation (a speed knob)"));
    t.push_back(
        choice_field<&RenderSettings::sampling>("sampling", "sampling", {"adaptive", "uniform"})
            .explain("spp > 1: stratified samples where the centre image has edges "
                     "(adaptive) or in every pixel (uniform)"));
    t.push_back(scalar_field<&RenderSettings::aa_threshold>(FieldKind::number, "aa_threshold",
                                                            "refine threshold")
                    .range(0.0, 1.0)
                    .ui(0.001, 0.25, true)
                    .explain("adaptive: refine where the displayed total (after exposure, tone, "
                             "clamp) curves by more than a tenth of this at a centre pixel"));
    t.push_back(scalar_field<&RenderSettings::env_resolution>(whole, "env_resolution",
                                                              "environment map resolution")
                    .range(1, 8)
                    .ui(1, 8)
                    .invalidates(ChangeClass::environment)
                    .explain("the fast path's prefiltered maps: texels per lobe width"));
    t.push_back(
        scalar_field<&RenderSettings::env_samples>(whole, "env_samples", "environment directions")
            .range(0, kMaxEnvSamples)
            .ui(0, 4096, true)
            .invalidates(ChangeClass::environment)
            .explain("directions per sample that converge on the environment's exact "
                     "terms (visibility included with shadows on); 0: the fast path "
                     "alone"));
    t.push_back(choice_field<&RenderSettings::map_filter>("map_filter", "map filter",
                                                          {"trilinear", "bilinear", "nearest"})
                    .invalidates(ChangeClass::texture)
                    .explain("maps read trilinear at each sample's footprint (the contract), or "
                             "bilinear or nearest at full resolution (knobs: they alias)"));
    return t;
  }();
  return table;
}

const FieldTable<Camera>& camera_fields() {
  static const FieldTable<Camera> table = [] {
    constexpr FieldKind vector = FieldKind::vector;
    FieldTable<Camera> t;
    t.push_back(vec3_field<&Camera::eye>(vector, "eye", "eye")
                    .range(-kMaxCoordinate, kMaxCoordinate)
                    .ui(-1e4, 1e4)
                    .explain("camera position, world units"));
    t.push_back(vec3_field<&Camera::target>(vector, "target", "target")
                    .range(-kMaxCoordinate, kMaxCoordinate)
                    .ui(-1e4, 1e4)
                    .explain("the point looked at; must differ from the eye"));
    t.push_back(vec3_field<&Camera::up>(vector, "up", "up")
                    .range(-kMaxCoordinate, kMaxCoordinate)
                    .ui(-1.0, 1.0)
                    .explain("up hint; not parallel to target - eye"));
    t.push_back(scalar_field<&Camera::fov_y>(FieldKind::number, "fov_y", "field of view")
                    .range(0.0, 180.0)
                    .open(true, true)
                    .ui(1.0, 150.0)
                    .explain("vertical field of view, degrees"));
    return t;
  }();
  return table;
}

const FieldTable<Environment>& environment_fields() {
  static const FieldTable<Environment> table = [] {
    FieldTable<Environment> t;
    // The engine keeps the environment's terms at intensity 1 and scales them as it recombines.
    t.push_back(scalar_field<&Environment::intensity>(FieldKind::number, "intensity", "intensity")
                    .range(0.0, 1e6)
                    .ui(0.0, 10.0)
                    .invalidates(ChangeClass::shade)
                    .explain("the map's radiance times this"));
    t.push_back(scalar_field<&Environment::rotation>(FieldKind::number, "rotation", "rotation")
                    .range(-1e6, 1e6)
                    .ui(-180.0, 180.0)
                    .invalidates(ChangeClass::environment)
                    .explain("degrees about the up axis; positive turns the map counter-clockwise "
                             "seen from above"));
    t.push_back(
        scalar_field<&Environment::as_background>(FieldKind::flag, "as_background", "as background")
            .invalidates(ChangeClass::shade)
            .explain("primary rays that hit nothing see the map; off: the background "
                     "colour"));
    return t;
  }();
  return table;
}

const FieldTable<Scene>& scene_fields() {
  static const FieldTable<Scene> table = [] {
    FieldTable<Scene> t;
    t.push_back(vec3_field<&Scene::background>(FieldKind::colour, "background", "background")
                    .invalidates(ChangeClass::shade)
                    .explain("the colour of primary rays that hit nothing"));
    t.push_back(vec3_field<&Scene::ambient>(FieldKind::colour, "ambient", "scene ambient")
                    .invalidates(ChangeClass::shade)
                    .explain("A_scene, the ambient light every ka sees"));
    return t;
  }();
  return table;
}

const FieldTable<ObjectTransform>& transform_fields() {
  static const FieldTable<ObjectTransform> table = [] {
    constexpr FieldKind vector = FieldKind::vector;
    FieldTable<ObjectTransform> t;
    t.push_back(vec3_field<&ObjectTransform::translate>(vector, "translate", "move")
                    .range(-kMaxCoordinate, kMaxCoordinate)
                    .ui(-100.0, 100.0)
                    .explain("added after rotation and scale, world units"));
    t.push_back(vec3_field<&ObjectTransform::rotate>(vector, "rotate", "rotate")
                    .range(-1e6, 1e6)
                    .ui(-360.0, 360.0)
                    .explain("degrees about x, then y, then z, about the pivot"));
    t.push_back(vec3_field<&ObjectTransform::scale>(vector, "scale", "scale")
                    .range(-kMaxCoordinate, kMaxCoordinate)
                    .ui(-10.0, 10.0)
                    .uniform_allowed()
                    .explain("per axis of the object's own frame, about the pivot; no axis 0; a "
                             "sphere's is uniform"));
    FieldTable<ObjectTransform>::value_type pivot =
        vec3_field<&ObjectTransform::pivot>(vector, "pivot", "pivot")
            .range(-kMaxCoordinate, kMaxCoordinate)
            .ui(-100.0, 100.0)
            .explain(
                "the point rotation and scale keep in place, world units; default: the "
                "object's own centre");
    // A pivot given by the file or the user stays; an unset one follows the centre.
    pivot.set = [](ObjectTransform& s, const FieldValue& value) {
      s.pivot = value.v;
      s.pivot_set = true;
    };
    t.push_back(pivot);
    for (auto& f : t) f.invalidates(ChangeClass::full);  // the geometry moves
    return t;
  }();
  return table;
}

const FieldTable<Object>& object_fields() {
  static const FieldTable<Object> table = [] {
    FieldTable<Object> t;
    // Hiding an object takes it out of the ray-scene queries: the geometry changes.
    t.push_back(scalar_field<&Object::hidden>(FieldKind::flag, "hidden", "hidden")
                    .invalidates(ChangeClass::full)
                    .explain("not rendered, casts no shadow, cannot be picked"));
    return t;
  }();
  return table;
}

bool operator==(const ObjectTransform& a, const ObjectTransform& b) {
  return same_fields(transform_fields(), a, b) && a.pivot_set == b.pivot_set;
}

bool operator==(const PhysicalReference& a, const PhysicalReference& b) {
  return same_fields(reference_fields(), a, b);
}

bool operator==(const Material& a, const Material& b) {
  return same_fields(material_fields(), a, b) && a.preset == b.preset && a.reference == b.reference;
}

bool operator==(const Light& a, const Light& b) {
  return same_fields(light_fields(), a, b);
}

bool operator==(const Environment& a, const Environment& b) {
  return same_fields(environment_fields(), a, b) && a.file == b.file && a.map == b.map;
}

bool operator==(const Camera& a, const Camera& b) {
  return same_fields(camera_fields(), a, b);
}

}  // namespace gloss
