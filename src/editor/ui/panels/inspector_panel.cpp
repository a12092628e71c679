// The pixel inspector window: what the contract computed at the centre of the pixel under the
// cursor (or the pinned one), term by term and light by light, from the reference path in double
// (reference/pixel_inspection.h). In the A/B view both sides are read, A and B as the viewport
// renders them (ab_compare.h: Phong | Blinn-Phong, or the snapshot | the live document).
#include <algorithm>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "editor/model/document/command_layer.h"
#include "editor/model/document/document.h"
#include "editor/ui/panels/panel_state.h"
#include "editor/ui/panels/panels.h"
#include "editor/ui/viewport/viewport.h"

namespace gloss {

namespace {

// The inspectors for the document as the viewport shows it: rebuilt when the document, the A/B
// split or its exponent rule changed (an Embree scene build each time, so only while the window
// is open).
void refresh(InspectorState& state, const ViewSettings& view, const CommandLayer& document,
             const std::optional<Snapshot>& taken) {
  const bool ab = view.mode == ViewMode::ab;
  const bool keep = view.keep_highlight_size;
  const AbSource source = view.ab_source;
  const std::uint64_t snapshot = taken ? taken->revision + 1 : 0;
  if (state.a && state.revision == document.revision() && state.ab == ab && state.keep == keep &&
      state.source == source && state.snapshot == snapshot) {
    return;
  }
  const Scene& scene = document.scene();
  state.a.reset();
  state.b.reset();
  try {
    if (ab) {
      // The same two documents the viewport's A/B renders (ab_compare.h).
      const AbScenes pair = ab_scenes(scene, source, taken ? &*taken : nullptr, keep);
      state.a = std::make_unique<PixelInspector>(pair.a);
      // The material | reference view's B side is not the Phong contract: not inspected.
      if (source != AbSource::reference) state.b = std::make_unique<PixelInspector>(pair.b);
    } else {
      state.a = std::make_unique<PixelInspector>(scene);
    }
    state.error.clear();
  } catch (const std::exception& e) {
    state.error = e.what();
  }
  state.revision = document.revision();
  state.ab = ab;
  state.keep = keep;
  state.source = source;
  state.snapshot = snapshot;
}

std::string rgb_text(const glm::dvec3& c) {
  char text[96];
  std::snprintf(text, sizeof text, "%.5g  %.5g  %.5g", c.x, c.y, c.z);
  return text;
}

std::string value_text(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

// One row: a name and one cell per side.
void row(const char* name, const std::string& a, const std::string* b) {
  ImGui::TableNextRow();
  ImGui::TableSetColumnIndex(0);
  ImGui::TextUnformatted(name);
  ImGui::TableSetColumnIndex(1);
  ImGui::TextUnformatted(a.c_str());
  if (b != nullptr) {
    ImGui::TableSetColumnIndex(2);
    ImGui::TextUnformatted(b->c_str());
  }
}

void rgb_row(const char* name, const glm::dvec3& a, const glm::dvec3* b) {
  const std::string bt = b != nullptr ? rgb_text(*b) : std::string();
  row(name, rgb_text(a), b != nullptr ? &bt : nullptr);
}

void value_row(const char* name, double a, const double* b) {
  const std::string bt = b != nullptr ? value_text(*b) : std::string();
  row(name, value_text(a), b != nullptr ? &bt : nullptr);
}

void text_row(const char* name, const std::string& a, const std::string* b) {
  row(name, a, b);
}

std::string object_text(const PixelBreakdown& r) {
  if (!r.hit) return "none (background)";
  return r.object_name.empty() ? "#" + std::to_string(r.object) : r.object_name;
}

std::string material_text(const PixelBreakdown& r) {
  if (!r.hit) return "none";
  return r.material_name.empty() ? "#" + std::to_string(r.material) : r.material_name;
}

// labels: the A and B column titles in the A/B view (ab_compare.h), else null.
void draw_table(const PixelBreakdown& a, const PixelBreakdown* b, const std::string* labels) {
  const int columns = b != nullptr ? 3 : 2;
  const ImGuiTableFlags flags =
      ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit;
  if (!ImGui::BeginTable("##inspector", columns, flags)) return;
  ImGui::TableSetupColumn("");
  ImGui::TableSetupColumn(b != nullptr                     ? labels[0].c_str()
                          : a.model == ShadingModel::phong ? "Phong"
                                                           : "Blinn-Phong");
  if (b != nullptr) ImGui::TableSetupColumn(labels[1].c_str());
  ImGui::TableHeadersRow();
  const std::string bo = b != nullptr ? object_text(*b) : "";
  const std::string bm = b != nullptr ? material_text(*b) : "";
  text_row("object", object_text(a), b != nullptr ? &bo : nullptr);
  text_row("material", material_text(a), b != nullptr ? &bm : nullptr);
  if (a.hit) {
    value_row("alpha", a.alpha, b != nullptr ? &b->alpha : nullptr);
    value_row("energy factor", a.energy_factor, b != nullptr ? &b->energy_factor : nullptr);
  }
  rgb_row("total", a.total, b != nullptr ? &b->total : nullptr);
  rgb_row("emissive", a.emissive, b != nullptr ? &b->emissive : nullptr);
  rgb_row("ambient", a.ambient, b != nullptr ? &b->ambient : nullptr);
  rgb_row("diffuse", a.diffuse, b != nullptr ? &b->diffuse : nullptr);
  rgb_row("specular", a.specular, b != nullptr ? &b->specular : nullptr);
  if (a.textured) {  // the maps: (u, v), and per map the level read and the texel it gave
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::TextDisabled("maps  (u, v) %.5g, %.5g", a.uv[0].x, a.uv[0].y);
    for (int s = 0; s < kMapSlots; ++s) {
      const MapReading& m = a.maps[s];
      if (!m.present) continue;
      const std::string name = std::string("  ") + to_string(static_cast<MapSlot>(s));
      const MapReading* mb = b != nullptr && b->textured ? &b->maps[s] : nullptr;
      const std::string bt = mb != nullptr ? rgb_text(glm::dvec3(mb->texel)) : std::string();
      row(name.c_str(), rgb_text(glm::dvec3(m.texel)), mb != nullptr ? &bt : nullptr);
      value_row("    level", m.level, mb != nullptr ? &mb->level : nullptr);
    }
  }
  for (std::size_t i = 0; i < a.lights.size(); ++i) {
    const LightBreakdown& l = a.lights[i];
    const LightBreakdown* lb = b != nullptr && i < b->lights.size() ? &b->lights[i] : nullptr;
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::TextDisabled("light %zu  (d = %.4g)", i, l.distance);
    value_row("  ndl", l.ndl, lb != nullptr ? &lb->ndl : nullptr);
    const char* cosine = b != nullptr                     ? "  c"
                         : a.model == ShadingModel::phong ? "  c = R.V"
                                                          : "  c = N.H";
    value_row(cosine, l.cosine, lb != nullptr ? &lb->cosine : nullptr);
    value_row("  c^alpha", l.cosine_power, lb != nullptr ? &lb->cosine_power : nullptr);
    value_row("  attenuation", l.attenuation, lb != nullptr ? &lb->attenuation : nullptr);
    value_row("  visibility", l.visibility, lb != nullptr ? &lb->visibility : nullptr);
    rgb_row("  diffuse", l.diffuse, lb != nullptr ? &lb->diffuse : nullptr);
    rgb_row("  specular", l.specular, lb != nullptr ? &lb->specular : nullptr);
  }
  ImGui::EndTable();
}

}  // namespace

void draw_inspector(InspectorState& state, ViewSettings& view, const CommandLayer& document,
                    const std::optional<Snapshot>& snapshot, const Viewport& viewport,
                    ImVec2 viewport_pos, ImVec2 viewport_size) {
  if (!view.show_inspector) return;
  // First shown in the viewport's lower right corner (over the floor of most scenes, the legend
  // of the A/B view); it can be moved.
  ImGui::SetNextWindowPos(
      ImVec2(viewport_pos.x + viewport_size.x - 8.0f, viewport_pos.y + viewport_size.y - 8.0f),
      ImGuiCond_FirstUseEver, ImVec2(1.0f, 1.0f));
  // Never taller or wider than the window: in a small one it scrolls (layout.cpp keeps it in).
  const ImVec2 window = ImGui::GetMainViewport()->Size;
  ImGui::SetNextWindowSizeConstraints(
      ImVec2(0, 0), ImVec2(window.x - 16.0f, window.y - 2.0f * ImGui::GetFrameHeight() - 16.0f));
  if (!ImGui::Begin("Pixel inspector", &view.show_inspector, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::End();
    return;
  }
  // It grows with its content (a second column in the A/B view): keep its right edge inside the
  // viewport while it fits there.
  const float right = viewport_pos.x + viewport_size.x;
  const ImVec2 at = ImGui::GetWindowPos(), extent = ImGui::GetWindowSize();
  if (at.x + extent.x > right && extent.x < viewport_size.x) {
    ImGui::SetWindowPos(ImVec2(right - extent.x, at.y));
  }
  const Scene& scene = document.scene();
  int x = view.inspect_x, y = view.inspect_y;
  if (!view.inspect_pinned) {
    x = viewport.hover_x();
    y = viewport.hover_y();
  }
  if (view.inspect_pinned) {
    ImGui::Text("pixel %d, %d of %d x %d  (pinned)", x, y, scene.render.width, scene.render.height);
    ImGui::SameLine();
    if (ImGui::SmallButton("unpin")) view.inspect_pinned = false;
  } else if (x >= 0) {
    ImGui::Text("pixel %d, %d of %d x %d  (under the cursor)", x, y, scene.render.width,
                scene.render.height);
  }
  ImGui::TextDisabled("hover the image; click to pin, click the pinned pixel to unpin");
  if (view.uv_checker) {
    // The checker is a view, not the document: the values below are the material's.
    ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.4f, 1.0f),
                       "UV checker on: the values are the material's, not the checker's");
  }
  if (x < 0 || y < 0 || x >= scene.render.width || y >= scene.render.height) {
    ImGui::TextUnformatted("no pixel: hover the render, a term view or the A/B view");
    ImGui::End();
    return;
  }
  refresh(state, view, document, snapshot);
  if (!state.error.empty() || !state.a) {
    ImGui::TextWrapped("cannot read this scene: %s", state.error.c_str());
    ImGui::End();
    return;
  }
  const PixelBreakdown a = state.a->inspect(x, y);
  ImGui::TextDisabled("the reference path in double, at the pixel centre");
  if (state.b) {
    const PixelBreakdown b = state.b->inspect(x, y);
    const glm::dvec3 d = glm::abs(a.total - b.total);
    ImGui::Text("|A - B| of the total: %.5g (largest channel)", std::max({d.x, d.y, d.z}));
    const std::string labels[2] = {ab_label_a(view.ab_source, snapshot ? &*snapshot : nullptr),
                                   ab_label_b(view.ab_source, view.keep_highlight_size)};
    draw_table(a, &b, labels);
  } else {
    if (view.mode == ViewMode::ab && view.ab_source == AbSource::reference) {
      ImGui::TextDisabled("A, the material; B is the physical reference (not a Phong reading)");
    }
    draw_table(a, nullptr, nullptr);
  }
  ImGui::End();
}

}  // namespace gloss
