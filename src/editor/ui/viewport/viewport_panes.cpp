// The viewport's panes: the textures drawn by the display shader into the off-screen target
// (one image, the 2x2 term sheet, or A/B with the heat map), their labels and the heat map's
// legend.
#include <algorithm>
#include <cstdio>

#include <glad/gl.h>

#include "editor/model/view/heat_map.h"
#include "editor/ui/viewport/viewport.h"

namespace gloss {

namespace {

float shown_heat_scale(const ViewSettings& view, float max_difference) {
  return view.heat_auto_scale ? std::max(max_difference, 1e-4f) : view.heat_scale;
}

}  // namespace

bool Viewport::TargetKey::operator==(const TargetKey& o) const {
  return uploads == o.uploads && width == o.width && height == o.height &&
         pane_count == o.pane_count && pane_x == o.pane_x && pane_y == o.pane_y &&
         pane_w == o.pane_w && pane_h == o.pane_h && mode == o.mode && single == o.single &&
         gain == o.gain && tone == o.tone && heat_scale == o.heat_scale && srgb == o.srgb &&
         show_clipped == o.show_clipped;
}

void Viewport::draw_panes(const ViewSettings& view, const DisplayTransform& display) {
  const int fw = std::max(1, static_cast<int>(m_size.x * m_framebuffer_scale));
  const int fh = std::max(1, static_cast<int>(m_size.y * m_framebuffer_scale));
  DisplayParams params;
  params.display = display;
  params.heat_scale = shown_heat_scale(view, m_max_difference);
  const TargetKey key{m_uploads,
                      fw,
                      fh,
                      m_pane_count,
                      m_panes[0].min.x - m_pos.x,
                      m_panes[0].min.y - m_pos.y,
                      m_panes[0].size.x,
                      m_panes[0].size.y,
                      view.mode,
                      view.single,
                      display.gain,
                      params.heat_scale,
                      display.tone,
                      display.srgb,
                      view.show_clipped};
  if (key == m_target_key && m_target.texture() != 0) return;
  m_target_key = key;
  // Texels map 1:1 to screen pixels at preview scale 1: nearest sampling is exact and cheaper.
  const bool one_to_one =
      m_total.width() == static_cast<int>(m_panes[0].size.x * m_framebuffer_scale) &&
      m_total.height() == static_cast<int>(m_panes[0].size.y * m_framebuffer_scale);
  for (GlTexture* t : {&m_total, &m_emissive, &m_ambient, &m_diffuse, &m_specular, &m_b_total}) {
    t->set_nearest(one_to_one);
  }
  m_target.resize(fw, fh);
  m_target.bind();
  glClearColor(0.11f, 0.11f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  for (int i = 0; i < m_pane_count; ++i) {
    const Pane& pane = m_panes[i];
    const int x = static_cast<int>((pane.min.x - m_pos.x) * m_framebuffer_scale);
    const int y_top = static_cast<int>((pane.min.y - m_pos.y) * m_framebuffer_scale);
    const int w = static_cast<int>(pane.size.x * m_framebuffer_scale);
    const int h = static_cast<int>(pane.size.y * m_framebuffer_scale);
    glViewport(x, fh - y_top - h, w, h);  // GL counts rows from the bottom
    const GlTexture* a = &m_total;
    const GlTexture* b = nullptr;
    params.mode = DisplayMode::image;
    params.clip_overlay = view.show_clipped;
    TermView term = TermView::total;
    if (view.mode == ViewMode::single) term = view.single;
    if (view.mode == ViewMode::terms) {
      const TermView sheet[4] = {TermView::emissive_ambient, TermView::diffuse, TermView::specular,
                                 TermView::total};
      term = sheet[i];
    }
    switch (term) {
      case TermView::emissive_ambient:
        a = &m_emissive;
        b = &m_ambient;
        params.mode = DisplayMode::sum;
        break;
      case TermView::emissive:
        a = &m_emissive;
        break;
      case TermView::ambient:
        a = &m_ambient;
        break;
      case TermView::diffuse:
        a = &m_diffuse;
        break;
      case TermView::specular:
        a = &m_specular;
        break;
      case TermView::total:
        break;
    }
    if (view.mode == ViewMode::ab) {
      a = i == 1 ? &m_b_total : &m_total;
      if (i == 2) {
        b = &m_b_total;
        params.mode = DisplayMode::heat;
      }
    }
    if (a->empty() || (b != nullptr && b->empty())) continue;
    m_shader.draw(a->id(), b != nullptr ? b->id() : 0, params);
  }
  RenderTarget::unbind();
}

void Viewport::draw_labels(const ViewSettings& view, ImDrawList* list) const {
  const char* labels[4] = {nullptr, nullptr, nullptr, nullptr};
  std::string single;
  if (view.mode == ViewMode::terms) {
    labels[0] = "emissive + ambient";
    labels[1] = "diffuse";
    labels[2] = "specular";
    labels[3] = "total";
  } else if (view.mode == ViewMode::single) {
    single = std::string(display_name(view.single)) + " only";
    labels[0] = single.c_str();
  } else if (view.mode == ViewMode::ab) {
    labels[0] = m_label_a.c_str();
    labels[1] = m_label_b.c_str();
    labels[2] = "|A - B| heat map";
  }
  for (int i = 0; i < m_pane_count; ++i) {
    const ImVec2 at(m_panes[i].min.x + 6.0f, m_panes[i].min.y + 4.0f);
    if (i > 0) {
      list->AddRect(
          m_panes[i].min,
          ImVec2(m_panes[i].min.x + m_panes[i].size.x, m_panes[i].min.y + m_panes[i].size.y),
          IM_COL32(60, 60, 66, 255));
    }
    if (m_fill) {
      // The document's frame (what an export of this pane holds) in a pane that shows more.
      const Pane& f = m_frames[i];
      list->AddRect(f.min, ImVec2(f.min.x + f.size.x, f.min.y + f.size.y),
                    IM_COL32(255, 255, 255, 70));
    }
    if (labels[i] == nullptr) continue;
    const ImVec2 text = ImGui::CalcTextSize(labels[i]);
    list->AddRectFilled(ImVec2(at.x - 3, at.y - 1), ImVec2(at.x + text.x + 3, at.y + text.y + 1),
                        IM_COL32(0, 0, 0, 160), 3.0f);
    list->AddText(at, IM_COL32(235, 235, 235, 255), labels[i]);
  }
}

void Viewport::draw_legend(const ViewSettings& view, ImDrawList* list, const Pane& pane) const {
  if (pane.size.x < 1.0f || pane.size.y < 1.0f) return;
  // Laid out in the legend's own room (pane_layout.h: beside, under or after the images):
  // title, ramp, ticks, the largest difference, the scale's kind, centred vertically.
  const float scale = shown_heat_scale(view, m_max_difference);
  const float line = ImGui::GetTextLineHeightWithSpacing();
  const float bar_h = 14.0f;
  const float content_h = line * 4.0f + bar_h + 6.0f;
  const float x0 = pane.min.x + 12.0f;
  const float x1 = pane.min.x + std::min(pane.size.x - 12.0f, 12.0f + 320.0f);
  float y = pane.min.y + std::max(4.0f, (pane.size.y - content_h) * 0.5f);
  const ImU32 text = IM_COL32(225, 225, 225, 255);
  list->PushClipRect(pane.min, ImVec2(pane.min.x + pane.size.x, pane.min.y + pane.size.y), true);
  list->AddText(ImVec2(x0, y), text, "|A - B|, largest channel");
  y += line;
  for (int i = 0; i + 1 < kHeatRampSize; ++i) {
    const float a = x0 + (x1 - x0) * static_cast<float>(i) / (kHeatRampSize - 1);
    const float b = x0 + (x1 - x0) * static_cast<float>(i + 1) / (kHeatRampSize - 1);
    const glm::vec3 ca = kHeatRamp[i], cb = kHeatRamp[i + 1];
    const ImU32 ua = ImGui::ColorConvertFloat4ToU32(ImVec4(ca.x, ca.y, ca.z, 1.0f));
    const ImU32 ub = ImGui::ColorConvertFloat4ToU32(ImVec4(cb.x, cb.y, cb.z, 1.0f));
    list->AddRectFilledMultiColor(ImVec2(a, y), ImVec2(b, y + bar_h), ua, ub, ub, ua);
  }
  list->AddRect(ImVec2(x0, y), ImVec2(x1, y + bar_h), IM_COL32(120, 120, 120, 255));
  y += bar_h + 3.0f;
  char tick[48];
  for (int i = 0; i <= 2; ++i) {
    std::snprintf(tick, sizeof tick, "%.3g", scale * 0.5f * static_cast<float>(i));
    const float x = x0 + (x1 - x0) * 0.5f * static_cast<float>(i);
    const float w = ImGui::CalcTextSize(tick).x;
    list->AddText(ImVec2(std::clamp(x - w * 0.5f, x0, x1 - w), y), text, tick);
  }
  y += line + 3.0f;
  char largest[96];
  std::snprintf(largest, sizeof largest, "max |A - B|: %.4g", m_max_difference);
  list->AddText(ImVec2(x0, y), text, largest);
  y += line;
  list->AddText(ImVec2(x0, y), IM_COL32(170, 170, 170, 255),
                view.heat_auto_scale ? "scale: automatic (the max)" : "scale: fixed (View panel)");
  list->PopClipRect();
}

}  // namespace gloss
