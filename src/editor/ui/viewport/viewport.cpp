#include "editor/ui/viewport/viewport.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include <GLFW/glfw3.h>
#include <glad/gl.h>

#include "editor/model/document/document.h"
#include "editor/model/view/heat_map.h"

namespace gloss {

namespace {

bool needs_terms(const ViewSettings& view) {
  return view.mode == ViewMode::terms ||
         (view.mode == ViewMode::single && view.single != TermView::total);
}

// terms: publish the four term images too (the term views only: four more images per pass).
std::unique_ptr<ProgressiveRenderer> make_cpu_renderer(bool terms) {
  ProgressiveOptions options;
  options.terms = terms;
  auto renderer = std::make_unique<ProgressiveRenderer>(options);
  // Runs on a render worker: wakes the event loop, which uploads the frame.
  renderer->set_on_publish([] { glfwPostEmptyEvent(); });
  return renderer;
}

// The material | reference view's B side; like the ray tracer, it wakes the event loop.
std::unique_ptr<ReferencePreview> make_reference_preview() {
  auto preview = std::make_unique<ReferencePreview>();
  preview->set_on_publish([] { glfwPostEmptyEvent(); });
  return preview;
}

}  // namespace

Viewport::Viewport() : m_a(make_cpu_renderer(false)) {}

Viewport::~Viewport() = default;

void Viewport::upload(const RenderedFrame& frame, bool b_side) {
  ++m_uploads;
  if (b_side) {
    m_b_total.upload(frame.images.total);
    return;
  }
  m_total.upload(frame.images.total);
  if (frame.images.emissive.width > 0 && m_pushed_terms) {
    m_emissive.upload(frame.images.emissive);
    m_ambient.upload(frame.images.ambient);
    m_diffuse.upload(frame.images.diffuse);
    m_specular.upload(frame.images.specular);
  }
}

void Viewport::max_difference_of_shown() {
  if (m_image_a && m_image_b) {
    m_max_difference = gloss::max_difference(m_image_a->images.total, m_image_b->images.total);
  }
}

void Viewport::upload_frames(double now_s) {
  // A side the ray tracer took over from the raster path keeps the raster frame until the ray
  // tracer's first full-size frame: its coarse previews would be a step back.
  auto takes = [&](const RenderedFrame& frame, bool shown_raster) {
    return !shown_raster ||
           (frame.info.width == m_render_width && frame.info.height == m_render_height);
  };
  // An A frame from before the raster path drew (a paused ray tracer's) is not the document's.
  auto current_a = [&](const RenderedFrame& frame) {
    return !m_shown_raster_a || frame.info.generation >= m_handover_generation;
  };
  bool new_a = false, new_b = false;
  if (m_a && !m_sides.a.raster) {
    if (std::shared_ptr<const RenderedFrame> a = m_a->latest();
        a && a != m_frame_a && takes(*a, m_shown_raster_a) && current_a(*a)) {
      upload(*a, false);
      // A full-size re-trace at one sample per pixel: a lower bound of the ray tracer's delay
      // in a drag, for Automatic (automatic_choice.h).
      const FrameInfo& info = a->info;
      if (info.cause == ChangeClass::full && info.spp == 1 && info.rays > 0 &&
          info.width == m_render_width && info.height == m_render_height) {
        m_automatic.ray_traced_pass(m_traced_setup, info.pass_ms);
      }
      m_frame_a = std::move(a);
      m_shown_raster_a = false;
      new_a = true;
    }
  }
  if ((m_b || m_reference) && !m_sides.b.raster) {
    if (std::shared_ptr<const RenderedFrame> b =
            m_reference ? m_reference->latest() : m_b->latest();
        b && b != m_frame_b && takes(*b, m_shown_raster_b)) {
      upload(*b, true);
      m_frame_b = std::move(b);
      m_shown_raster_b = false;
      new_b = true;
    }
  }
  // What the textures hold: the newest frames with a total image. A frame without one (the
  // engine's adaptive refinement passes publish an empty total when the terms are off, as of
  // the adaptive-AA merge) leaves the texture, and these, as they were.
  if (new_a && m_frame_a->images.total.width > 0) m_image_a = m_frame_a;
  if (new_b && m_frame_b->images.total.width > 0) m_image_b = m_frame_b;
  if (new_a || new_b) max_difference_of_shown();
  // A new frame of the side the newest edit changed (sync: in the snapshot | live view an edit
  // changes only B) shows edits; a new frame of the other side is a new image of no edit.
  const bool watched_new = m_watch_b ? new_b : new_a;
  if (watched_new) {
    const RenderedFrame& watched = m_watch_b ? *m_frame_b : *m_frame_a;
    m_show_pending = true;
    m_show_generation = watched.info.generation;
    m_show_full = watched.info.width == m_render_width && watched.info.height == m_render_height;
  } else if ((new_a || new_b) && !m_show_pending) {
    m_show_pending = true;
    m_show_generation = 0;
    m_show_full = false;
  }
  (void)now_s;
}

void Viewport::forget_edits() {
  m_cadence.forget_pending();
  m_edit_tags.clear();
}

void Viewport::frame_shown(double now_s) {
  if (!m_show_pending) return;
  m_show_pending = false;
  const ImageCadence::Delays d = m_cadence.shown(m_show_generation, m_show_full, now_s);
  if (d.first_ms >= 0.0) m_latency.first_image_ms = d.first_ms;
  if (d.full_ms >= 0.0) {
    m_latency.full_image_ms = d.full_ms;
    // A drag's delay goes to Automatic under the setup of its own edit.
    for (const EditTag& tag : m_edit_tags) {
      if (tag.generation == d.generation && tag.drag) {
        m_automatic.drag_image(tag.setup, m_shown_raster_a, d.full_ms);
      }
    }
  }
  // Older edits are done with; the image's own edit keeps its tag until its full-size image
  // (a preview shown first used to drop it, and with it a drag's delay whenever the ray tracer
  // was slow enough to show previews: Automatic then never timed the ray tracer's drags).
  while (!m_edit_tags.empty() &&
         (m_edit_tags.front().generation < d.generation ||
          (m_edit_tags.front().generation == d.generation && d.full_ms >= 0.0))) {
    m_edit_tags.pop_front();
  }
}

void Viewport::sync(const Scene& document, std::uint64_t revision, const ViewSettings& view,
                    const Snapshot* snapshot, double now_s) {
  if (m_panes[0].size.x < 1.0f || m_panes[0].size.y < 1.0f) return;  // no layout yet
  // The panes were laid out by draw() this frame, in the document's aspect.
  const float scale = m_framebuffer_scale * view.preview_scale;
  const int width = std::clamp(static_cast<int>(m_panes[0].size.x * scale), 1, kMaxImageSide);
  const int height = std::clamp(static_cast<int>(m_panes[0].size.y * scale), 1, kMaxImageSide);
  const bool terms = needs_terms(view);
  const bool ab = view.mode == ViewMode::ab;
  const std::uint64_t snapshot_revision =
      snapshot != nullptr ? snapshot->revision + 1 : 0;  // 0: none
  m_setup = drag_setup(document, width, height, terms, ab, view.raster, m_drag_light >= 0);
  AbSides sides{{raster_effective(view, now_s), view.raster.shading}, {}};
  if (ab) sides = ab_sides(view.ab_source, sides.a.raster, view.raster.shading);
  if ((sides.a.raster || sides.b.raster) && !raster_available()) {
    sides.a.raster = sides.b.raster = false;
  }
  RasterKey key{revision,
                ab ? snapshot_revision : 0,
                width,
                height,
                terms,
                ab,
                ab && view.keep_highlight_size,
                ab ? view.ab_source : AbSource::models,
                sides,
                view.raster};
  key.settings.shading = ShadingFrequency::pixel;  // each side's frequency is in sides
  key.lights = document.lights.size();
  // The raster path failed with this setup: the ray tracer draws until the setup changes.
  if (m_raster_render_failed && key.same_setup(m_raster_key)) {
    sides.a.raster = sides.b.raster = false;
  }
  m_pushed_renderer = view.renderer;
  m_pushed_raster = view.raster;

  const bool changed =
      !m_pushed_any || revision != m_pushed_revision || width != m_render_width ||
      height != m_render_height || terms != m_pushed_terms ||
      ab != (m_pushed_mode == ViewMode::ab) || (ab && view.keep_highlight_size != m_pushed_keep) ||
      (ab && view.ab_source != m_pushed_source) ||
      (ab && view.ab_source == AbSource::snapshot && snapshot_revision != m_pushed_snapshot) ||
      !(sides.a == m_sides.a) || !(sides.b == m_sides.b);
  const bool raster_dirty =
      (sides.a.raster || sides.b.raster) && (!m_raster_shown || !(key == m_raster_key));
  if (!changed && !raster_dirty) {
    // A mode switch that needs no new render (render, total alone, lobe) still counts as shown
    // in the new mode (converged_and_shown compares it).
    m_pushed_mode = view.mode;
    return;
  }

  const bool new_edit = m_pushed_any && revision != m_pushed_revision;
  Scene scene = document;
  scene.render.width = width;
  scene.render.height = height;
  AbScenes pair = ab ? ab_scenes(scene, view.ab_source, snapshot, view.keep_highlight_size)
                     : AbScenes{std::move(scene), Scene{}};
  pair.a.render.width = pair.b.render.width = width;  // the snapshot has its own size
  pair.a.render.height = pair.b.render.height = height;
  if (m_fill) {
    // Panes that fill their cells show each side's view, in the document's frame, and more
    // around it (pane_camera); the snapshot keeps its own camera.
    Scene framed = document;
    for (Scene* side : {&pair.a, &pair.b}) {
      framed.camera = side->camera;
      side->camera = pane_camera(framed);
    }
  }
  std::uint64_t pushed_generation = 0;    // what the A side's ray tracer returned, 0: not handed
  std::uint64_t pushed_generation_b = 0;  // the same for the B side
  bool a_changed = false, b_changed = false;  // a side's ray tracer has a new generation
  if (changed) {
    if (!terms) {
      // Textures the view no longer shows: llvmpipe keeps each in RAM (12 B per pixel).
      m_emissive = GlTexture();
      m_ambient = GlTexture();
      m_diffuse = GlTexture();
      m_specular = GlTexture();
    }
    if (sides.a.raster && view.renderer == RendererChoice::automatic && m_a) {
      // A drag drawn by the raster path: the ray tracer waits for its end with its scene, BVH
      // and caches kept, instead of sharing the cores meanwhile.
      m_a->pause();
    } else if (sides.a.raster) {
      m_a.reset();  // cancels and joins its worker: the raster path draws A
    } else {
      if (!m_a) {
        m_a = make_cpu_renderer(terms);
        m_automatic.ray_tracer_restarted();
        m_last_generation_a = 0;
        forget_edits();  // a new renderer counts its generations from 1 again
      } else {
        m_a->set_terms(terms);  // no work when unchanged; also a view switched while paused
      }
      pushed_generation = m_a->set_scene(pair.a);
      a_changed = pushed_generation != m_last_generation_a;
      m_last_generation_a = pushed_generation;
      // Taking over from the raster path: frames of older generations show the scene before it.
      if (m_shown_raster_a) m_handover_generation = pushed_generation;
      m_traced_setup = m_setup;
    }
    if (ab && sides.b.physical) {
      m_b.reset();
      if (!m_reference) {
        m_reference = make_reference_preview();
        m_last_generation_b = 0;
        forget_edits();
      }
      pushed_generation_b = m_reference->set_scene(pair.b);
      b_changed = pushed_generation_b != m_last_generation_b;
      m_last_generation_b = pushed_generation_b;
    } else if (ab && !sides.b.raster) {
      m_reference.reset();
      if (!m_b) {
        m_b = make_cpu_renderer(false);
        m_last_generation_b = 0;
        forget_edits();
      }
      pushed_generation_b = m_b->set_scene(pair.b);
      b_changed = pushed_generation_b != m_last_generation_b;
      m_last_generation_b = pushed_generation_b;
    } else {
      m_b.reset();
      m_reference.reset();
    }
    if (!ab) {
      m_frame_b.reset();
      m_b_total = GlTexture();
      m_image_b.reset();
      m_shown_raster_b = false;
    } else {
      m_label_a = ab_label_a(view.ab_source, snapshot);
      m_label_b = ab_label_b(view.ab_source, view.keep_highlight_size, view.raster.shading);
      if (!sides.b.raster &&
          (view.ab_source == AbSource::cpu_gl || view.ab_source == AbSource::pixel_vertex)) {
        m_label_b += " - raster unavailable, ray traced";
      }
      const auto has_reference = [](const Material& m) { return m.reference.has_value(); };
      if (view.ab_source == AbSource::reference &&
          std::none_of(document.materials.begin(), document.materials.end(), has_reference)) {
        m_label_b += " - none set";
      }
    }
    m_pushed_any = true;
    m_pushed_revision = revision;
    m_render_width = width;
    m_render_height = height;
    m_pushed_terms = terms;
    m_pushed_mode = view.mode;
    m_pushed_keep = view.keep_highlight_size;
    m_pushed_source = view.ab_source;
    m_pushed_snapshot = snapshot_revision;
    m_sides = sides;
  }
  if (new_edit) {
    // now_s is the start of the frame in which the edit happened. Frames of the generation the
    // ray tracer was handed with it, or later, show it; an edit the raster path draws (no
    // generation) is shown by its raster frame (kNewest). The side watched is the one the edit
    // changed: in the snapshot | live view an edit changes only B (live); watching A there,
    // whose frames never came, made the next view switch read as the edit's delay (20 to 127 s).
    // Generations count per renderer, so a switch of side forgets the other side's edits.
    const bool watch_b = b_changed && !a_changed;
    if (watch_b != m_watch_b) {
      forget_edits();
      m_watch_b = watch_b;
    }
    // An edit that changed no ray-traced side (a raster side shows it below; a name changes no
    // image) is not waited for: a later, unrelated frame would read as its delay.
    const bool raster_side = sides.a.raster || (ab && sides.b.raster);
    if (a_changed || b_changed || raster_side) {
      // The watched side's newest generation (on a raster-drawn edit, A's last one).
      const std::uint64_t generation = m_watch_b ? m_last_generation_b : m_last_generation_a;
      m_cadence.edit(generation, now_s);
      if (m_edit_tags.empty() || m_edit_tags.back().generation < generation) {
        m_edit_tags.push_back({generation, moving_gesture(now_s), m_setup});
        if (m_edit_tags.size() > 4096) m_edit_tags.pop_front();  // frames that never come
      } else {
        m_edit_tags.back() = {generation, moving_gesture(now_s), m_setup};
      }
    }
  }
  if (raster_dirty) {
    m_raster_key = key;
    m_raster_render_failed = !show_raster(pair, sides, view.raster, terms, ab, now_s);
    if (m_raster_render_failed) glfwPostEmptyEvent();  // the next sync hands it to the ray tracer
  } else if (!sides.a.raster && !sides.b.raster) {
    m_raster_shown = false;
  }
}

void Viewport::blit(int framebuffer_height) const {
  if (!m_visible || m_target.texture() == 0) return;
  const int x = static_cast<int>(m_pos.x * m_framebuffer_scale);
  const int top = static_cast<int>(m_pos.y * m_framebuffer_scale);
  m_target.blit_to_window(x, framebuffer_height - top - m_target.height());
}

bool Viewport::converged_and_shown(std::uint64_t revision, const ViewSettings& view) const {
  if (!m_pushed_any || revision != m_pushed_revision || view.mode != m_pushed_mode ||
      needs_terms(view) != m_pushed_terms || view.renderer != m_pushed_renderer ||
      view.raster != m_pushed_raster ||
      (view.mode == ViewMode::ab && view.ab_source != m_pushed_source)) {
    return false;
  }
  // The lobe view's albedo plot is shown once its curves (a worker's) are the current ones.
  if (view.mode == ViewMode::lobe && view.lobe_plot == LobePlot::albedo &&
      (!m_lobe.albedo.current() ||
       (view.lobe_overlay != LobeOverlay::none && m_lobe.overlay_albedo.busy()))) {
    return false;
  }
  // A raster frame is final once it is on screen; the ray tracer's when it has converged.
  auto side_done = [&](const AbSide& side, const ProgressiveRenderer* renderer,
                       const std::shared_ptr<const RenderedFrame>& frame, bool shown_raster) {
    if (frame == nullptr) return false;
    if (side.raster) return m_raster_shown && shown_raster;
    if (side.physical) {
      return m_reference != nullptr && m_reference->wait_converged(0.0) &&
             m_reference->latest() == frame;
    }
    return renderer != nullptr && renderer->wait_converged(0.0) && renderer->latest() == frame;
  };
  if (!side_done(m_sides.a, m_a.get(), m_frame_a, m_shown_raster_a)) return false;
  return m_pushed_mode != ViewMode::ab ||
         side_done(m_sides.b, m_b.get(), m_frame_b, m_shown_raster_b);
}

bool Viewport::gesture_active(double now_s) const {
  return m_drag_button >= 0 || (m_last_wheel_s >= 0.0 && now_s - m_last_wheel_s < 0.6);
}

}  // namespace gloss
