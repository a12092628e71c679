#include "editor/gl/raster/raster_renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "editor/gl/raster/environment_texture.h"
#include "editor/gl/raster/map_textures.h"
#include "editor/gl/raster/raster_geometry.h"
#include "editor/gl/raster/raster_programs.h"
#include "editor/gl/raster/raster_uniforms.h"
#include "editor/gl/raster/raster_view.h"
#include "editor/gl/raster/shadow_maps.h"
#include "engine/frame_pool.h"
#include "texture/footprint.h"

namespace gloss {

namespace {

using Clock = std::chrono::steady_clock;

constexpr int kTargets = 5;  // total, emissive, ambient, diffuse, specular (raster_mesh.frag)

double finish_ms(Clock::time_point& since) {
  glFinish();  // llvmpipe and GPUs alike: the phase's work is done when the clock stops
  const Clock::time_point now = Clock::now();
  const double ms = std::chrono::duration<double, std::milli>(now - since).count();
  since = now;
  return ms;
}

// The GL state the renderer changes, put back afterwards so the caller's drawing is not
// disturbed (the editor resets what it uses anyway; tests and the tradeoff rows do not).
struct SavedState {
  GLint draw_framebuffer = 0, read_framebuffer = 0, program = 0, vertex_array = 0;
  GLint array_buffer = 0, renderbuffer = 0, viewport[4] = {};
  GLint active_texture = GL_TEXTURE0, texture_2d = 0, texture_array = 0;  // on unit 0
  GLint texture_2d_unit1 = 0;                                             // the environment's unit
  GLint front_face = GL_CCW, cull_face = GL_BACK, depth_func = GL_LESS;
  GLint blend_rgb = GL_FUNC_ADD, blend_alpha = GL_FUNC_ADD, pack_alignment = 4;
  GLboolean depth_test = GL_FALSE, blend = GL_FALSE, cull = GL_FALSE;
  SavedState() {
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw_framebuffer);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read_framebuffer);
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertex_array);
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &array_buffer);
    glGetIntegerv(GL_RENDERBUFFER_BINDING, &renderbuffer);
    glGetIntegerv(GL_VIEWPORT, viewport);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active_texture);
    glActiveTexture(GL_TEXTURE1);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture_2d_unit1);
    glActiveTexture(GL_TEXTURE0);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture_2d);
    glGetIntegerv(GL_TEXTURE_BINDING_2D_ARRAY, &texture_array);
    glGetIntegerv(GL_FRONT_FACE, &front_face);
    glGetIntegerv(GL_CULL_FACE_MODE, &cull_face);
    glGetIntegerv(GL_DEPTH_FUNC, &depth_func);
    glGetIntegerv(GL_BLEND_EQUATION_RGB, &blend_rgb);
    glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &blend_alpha);
    glGetIntegerv(GL_PACK_ALIGNMENT, &pack_alignment);
    depth_test = glIsEnabled(GL_DEPTH_TEST);
    blend = glIsEnabled(GL_BLEND);
    cull = glIsEnabled(GL_CULL_FACE);
  }
  ~SavedState() {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(draw_framebuffer));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(read_framebuffer));
    glUseProgram(static_cast<GLuint>(program));
    glBindVertexArray(static_cast<GLuint>(vertex_array));
    glBindBuffer(GL_ARRAY_BUFFER, static_cast<GLuint>(array_buffer));
    glBindRenderbuffer(GL_RENDERBUFFER, static_cast<GLuint>(renderbuffer));
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    glActiveTexture(GL_TEXTURE0);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(texture_2d_unit1));
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(texture_2d));
    glBindTexture(GL_TEXTURE_2D_ARRAY, static_cast<GLuint>(texture_array));
    glActiveTexture(static_cast<GLenum>(active_texture));
    glFrontFace(static_cast<GLenum>(front_face));
    glCullFace(static_cast<GLenum>(cull_face));
    glDepthFunc(static_cast<GLenum>(depth_func));
    glBlendEquationSeparate(static_cast<GLenum>(blend_rgb), static_cast<GLenum>(blend_alpha));
    glPixelStorei(GL_PACK_ALIGNMENT, pack_alignment);
    depth_test ? glEnable(GL_DEPTH_TEST) : glDisable(GL_DEPTH_TEST);
    blend ? glEnable(GL_BLEND) : glDisable(GL_BLEND);
    cull ? glEnable(GL_CULL_FACE) : glDisable(GL_CULL_FACE);
  }
};

// The objects view may see, meshes before spheres, each nearest first: the depth test then
// rejects hidden fragments before they are shaded (early depth test; impostors write
// gl_FragDepth and get none).
std::vector<const Object*> draw_order(const Scene& scene, const std::vector<DrawnBox>& boxes,
                                      const RasterView& view) {
  std::vector<std::pair<float, const Object*>> keyed;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    if (!may_be_seen(view, boxes[i])) continue;
    const Object& o = scene.objects[i];
    const float distance = glm::length(0.5f * (boxes[i].lo + boxes[i].hi) - view.origin);
    keyed.emplace_back(o.type == ObjectType::sphere ? distance + 1e30f : distance, &o);
  }
  std::stable_sort(keyed.begin(), keyed.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<const Object*> order;
  for (const auto& k : keyed) order.push_back(k.second);
  return order;
}

}  // namespace

struct RasterRenderer::Impl {
  explicit Impl(SourceEdit edit) : programs(std::move(edit)) {}

  RasterPrograms programs;
  RasterGeometry geometry;
  MapTextures maps;
  ShadowMaps shadows;
  EnvironmentTexture environment;  // the environment's levels (texture unit 1)
  bool with_environment = false;   // of the frame being drawn
  RasterTiming timing;

  // The five float targets and their depth buffer, resized with the image.
  GLuint framebuffer = 0, targets[kTargets] = {}, depth = 0;
  int width = 0, height = 0;

  ~Impl() {
    if (framebuffer != 0) glDeleteFramebuffers(1, &framebuffer);
    if (targets[0] != 0) glDeleteTextures(kTargets, targets);
    if (depth != 0) glDeleteRenderbuffers(1, &depth);
  }

  void size_targets(int w, int h) {
    if (framebuffer != 0 && w == width && h == height) return;
    if (framebuffer == 0) {
      glGenFramebuffers(1, &framebuffer);
      glGenTextures(kTargets, targets);
      glGenRenderbuffers(1, &depth);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    GLenum buffers[kTargets];
    for (int i = 0; i < kTargets; ++i) {
      glBindTexture(GL_TEXTURE_2D, targets[i]);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, w, h, 0, GL_RGBA, GL_FLOAT, nullptr);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      buffers[i] = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i);
      glFramebufferTexture2D(GL_FRAMEBUFFER, buffers[i], GL_TEXTURE_2D, targets[i], 0);
    }
    glBindRenderbuffer(GL_RENDERBUFFER, depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, w, h);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    glDrawBuffers(kTargets, buffers);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      throw std::runtime_error("the raster path's float render targets are not supported here");
    }
    width = w;
    height = h;
  }

  // Draws every object of scene into the current framebuffer from view, with the programs of
  // pass (one per shape); material uniforms only for the shading passes.
  void draw_objects(const Scene& scene, const RasterView& view, RasterPass pass, bool shadows) {
    const int lights = static_cast<int>(scene.lights.size());
    GLuint current = 0;
    // gloss_project negates y, which turns the cube's outward counter-clockwise triangles
    // clockwise on screen in the camera's right-handed frame, and keeps them counter-clockwise
    // in a cube face's left-handed one.
    const bool left_handed = glm::dot(glm::cross(view.right, view.up), view.forward) > 0.0f;
    glFrontFace(left_handed ? GL_CCW : GL_CW);
    // The ray cone of one pixel at unit distance (texture/footprint.h), for the maps.
    const float spread = cone_spread(scene.camera.fov_y, scene.render.height, 1);
    // The light types and shadow-map kinds present, so each program holds only their code.
    int light_types = 0, shadow_kinds = 0;
    for (const Light& light : scene.lights) light_types |= 1 << static_cast<int>(light.type);
    if (shadows) {
      for (const LightShadow& l : this->shadows.lights()) shadow_kinds |= 1 << l.kind;
    }
    for (const Object* object : draw_order(scene, boxes, view)) {
      const Object& o = *object;
      const bool sphere = o.type == ObjectType::sphere;
      const Material& material = scene.materials.at(static_cast<std::size_t>(o.material));
      // Spheres are impostors: per pixel in both shading passes.
      const RasterPass own = sphere && pass == RasterPass::vertex ? RasterPass::pixel : pass;
      // Shadow passes need maps only to cut out.
      const bool with_maps =
          pass == RasterPass::shadow ? material.has_map(MapSlot::opacity) : material.textured();
      RasterVariant variant{sphere ? RasterShape::sphere : RasterShape::mesh, own, lights, shadows,
                            with_environment && pass != RasterPass::shadow};
      variant.maps = with_maps;
      variant.light_types = light_types;
      variant.model = scene.render.model == ShadingModel::phong ? 0 : 1;
      variant.energy_normalize = scene.render.energy_normalize;
      // A shadow pass draws one kind of view: orthographic, or perspective (cubes, spots).
      variant.shadow_kinds = pass != RasterPass::shadow ? shadow_kinds
                             : view.orthographic
                                 ? 1 << LightShadow::orthographic
                                 : (1 << LightShadow::cube) | (1 << LightShadow::perspective);
      const GLuint program = programs.get(variant);
      if (program != current) {
        glUseProgram(program);
        current = program;
        set_view_uniforms(program, view);
        if (pass != RasterPass::shadow) {
          set_scene_uniforms(program, scene);
          set_uniform(program, "gloss_image_size", float(width), float(height));
          if (with_environment) environment.use(program, scene, 1);
          if (shadows) {
            set_uniform(program, "gloss_shadow_maps", 0);
            set_uniform(program, "gloss_shadow_size", float(this->shadows.size()));
            set_uniform(program, "gloss_shadow_bias", shadow_bias);
            set_shadow_uniforms(program, this->shadows.lights());
          }
        }
      }
      if (pass != RasterPass::shadow) set_material_uniforms(program, material);
      // Units 2..9 (0 holds the shadow maps, 1 the environment's levels).
      if (with_maps) set_map_uniforms(program, maps, material, scene.render.map_filter, spread, 2);
      if (sphere) {
        set_uniform(program, "gloss_sphere_centre", &o.center.x);
        set_uniform(program, "gloss_sphere_radius", o.radius);
        // Only the near faces when they cover the sphere (near_faces_suffice): the far ones
        // would shade the same pixels again, and impostors (which write depth) are shaded
        // before the depth test rejects them. Otherwise both.
        const DrawnBox& cube = boxes[static_cast<std::size_t>(object - scene.objects.data())];
        if (near_faces_suffice(view, cube)) glEnable(GL_CULL_FACE);
        glBindVertexArray(geometry.cube());
        glDrawArrays(GL_TRIANGLES, 0, 36);
        glDisable(GL_CULL_FACE);
      } else if (o.mesh && !o.mesh->triangles.empty()) {
        const MeshBuffer& b = geometry.mesh(*o.mesh);
        glBindVertexArray(b.vertex_array);
        glDrawArrays(GL_TRIANGLES, 0, b.vertices);
      }
    }
  }

  // The environment where primary rays miss: one triangle over the image, before the objects,
  // without depth.
  void draw_sky(const Scene& scene, const RasterView& view) {
    const GLuint program = programs.get({RasterShape::sky, RasterPass::pixel, 0, false, true});
    glUseProgram(program);
    set_view_uniforms(program, view);
    set_uniform(program, "gloss_image_size", float(width), float(height));
    environment.use(program, scene, 1);
    glDisable(GL_DEPTH_TEST);
    glBindVertexArray(geometry.cube());  // core GL needs one bound; the sky reads no attribute
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEnable(GL_DEPTH_TEST);
  }

  float shadow_bias = 0.0f;
  std::vector<DrawnBox> boxes;  // of the frame being drawn, by object
  std::shared_ptr<FramePool> frames = std::make_shared<FramePool>();
};

RasterRenderer::RasterRenderer(SourceEdit edit) : m_impl(std::make_unique<Impl>(std::move(edit))) {
  // Build the programs a scene of one point light with shadows draws with (the default scene's)
  // now, so that a shader that does not compile on this driver is reported when the raster path
  // is chosen, not mid-frame, and the first frame finds them built. Programs of other light
  // types and map kinds are built when a scene first needs them.
  for (RasterShape shape : {RasterShape::mesh, RasterShape::sphere}) {
    for (RasterPass pass : {RasterPass::shadow, RasterPass::pixel, RasterPass::vertex}) {
      if (shape == RasterShape::sphere && pass == RasterPass::vertex) continue;
      RasterVariant variant{shape, pass, 1, pass != RasterPass::shadow};
      variant.light_types = 1 << static_cast<int>(LightType::point);
      variant.shadow_kinds = pass == RasterPass::shadow
                                 ? (1 << LightShadow::cube) | (1 << LightShadow::perspective)
                                 : 1 << LightShadow::cube;
      m_impl->programs.get(variant);
    }
  }
}

RasterRenderer::~RasterRenderer() = default;

const RasterTiming& RasterRenderer::timing() const {
  return m_impl->timing;
}

std::shared_ptr<RenderedFrame> RasterRenderer::render(const Scene& scene,
                                                      const RasterSettings& settings, bool terms) {
  const int lights = static_cast<int>(scene.lights.size());
  if (lights > kMaxRasterLights) {
    throw std::runtime_error("the raster path takes at most " + std::to_string(kMaxRasterLights) +
                             " lights; this scene has " + std::to_string(lights));
  }
  if (settings.shadow_map_size < kMinShadowMapSize ||
      settings.shadow_map_size > kMaxShadowMapSize) {
    throw std::invalid_argument("shadow map size " + std::to_string(settings.shadow_map_size) +
                                " is outside " + std::to_string(kMinShadowMapSize) + ".." +
                                std::to_string(kMaxShadowMapSize));
  }
  const int w = scene.render.width, h = scene.render.height;
  if (w < 1 || h < 1) {
    throw std::invalid_argument("raster image size " + std::to_string(w) + "x" + std::to_string(h) +
                                " is empty");
  }
  Impl& m = *m_impl;
  m.boxes = drawn_boxes(scene);
  const RasterView view = camera_view(scene, m.boxes, w, h);  // throws for a degenerate camera
  // An error left pending by earlier GL calls is not the raster path's (checked at the end).
  for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i) {
  }
  const SavedState saved;
  // Two-sided surfaces: no culling but for impostor cubes seen from outside (draw_objects).
  glDisable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  RasterTiming& t = m.timing;
  t = {};
  Clock::time_point since = Clock::now();

  m.geometry.sync(scene);
  m.maps.sync(scene);
  t.upload_ms = finish_ms(since);

  const bool shadows = scene.render.shadows && lights > 0;
  if (shadows) {
    m.shadows.update(scene, m.boxes, settings.shadow_map_size, [&](const RasterView& face) {
      m.draw_objects(scene, face, RasterPass::shadow, false);
    });
    t.shadow_ms = finish_ms(since);
  }

  m.with_environment = scene.environment.present();
  if (m.with_environment) m.environment.update(scene);

  m.size_targets(w, h);
  glBindFramebuffer(GL_FRAMEBUFFER, m.framebuffer);
  glViewport(0, 0, w, h);
  // A miss: the background in the total, 0 in every term (docs/spec/shading.md, first section).
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  const float background[4] = {scene.background.x, scene.background.y, scene.background.z, 0.0f};
  // Without terms only the total is written: on llvmpipe every float target costs memory
  // traffic per covered pixel (the unused outputs are dropped, not stored).
  const int targets = terms ? kTargets : 1;
  GLenum buffers[kTargets];
  for (int i = 0; i < kTargets; ++i) buffers[i] = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i);
  glDrawBuffers(targets, buffers);
  glClearBufferfv(GL_COLOR, 0, background);
  for (int i = 1; i < targets; ++i) glClearBufferfv(GL_COLOR, i, zero);
  const float far_depth = 1.0f;
  glClearBufferfv(GL_DEPTH, 0, &far_depth);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_BLEND);
  if (shadows) {
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D_ARRAY, m.shadows.texture());
  }
  m.shadow_bias = settings.shadow_bias;
  if (m.with_environment && scene.environment.as_background) m.draw_sky(scene, view);
  m.draw_objects(
      scene, view,
      settings.shading == ShadingFrequency::vertex ? RasterPass::vertex : RasterPass::pixel,
      shadows);
  t.draw_ms = finish_ms(since);

  // Recycled images: a fresh 11 MB buffer per image cost its page faults, more than reading it
  // back (4 ms against 2.5 ms per image at 1280x720 here).
  std::shared_ptr<RenderedFrame> frame = FramePool::make(m.frames, w, h, terms);
  Image* images[kTargets] = {&frame->images.total, &frame->images.emissive, &frame->images.ambient,
                             &frame->images.diffuse, &frame->images.specular};
  glPixelStorei(GL_PACK_ALIGNMENT, 4);  // rows of vec3 floats: 12 w bytes, a multiple of 4
  for (int i = 0; i < targets; ++i) {
    glReadBuffer(GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i));
    // gloss_project negates y: GL's row 0 is the image's top row, as Image stores it.
    glReadPixels(0, 0, w, h, GL_RGB, GL_FLOAT, images[i]->pixels.data());
  }
  t.readback_ms = finish_ms(since);
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) {
    throw std::runtime_error("the raster path hit GL error " + std::to_string(error));
  }

  FrameInfo& info = frame->info;
  info.width = w;
  info.height = h;
  info.spp = 1;
  info.target_spp = 1;
  info.pass_ms = t.total_ms();
  info.since_change_ms = t.total_ms();
  info.converged = true;
  return frame;
}

}  // namespace gloss
