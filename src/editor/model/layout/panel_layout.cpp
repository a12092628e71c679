#include "editor/model/layout/panel_layout.h"

#include <algorithm>
#include <cmath>

namespace gloss {

namespace {

// The default width of a side panel: a quarter of the window, within 220..380 pixels: at a
// laptop's 1024 the two take exactly the half the viewport leaves them.
float default_width(float width) {
  return std::clamp(std::floor(width * 0.25f), kMinPanelWidth, 380.0f);
}

float min_width(float width) {
  return std::min(kMinPanelWidth, std::floor(width * 0.25f));
}

}  // namespace

void clamp_panel_widths(PanelChoices& c, float width) {
  const float lo = min_width(width), hi = std::max(lo, std::floor(width * 0.4f));
  if (c.left_width <= 0.0f) c.left_width = default_width(width);
  if (c.right_width <= 0.0f) c.right_width = default_width(width);
  c.left_width = std::clamp(c.left_width, lo, hi);
  c.right_width = std::clamp(c.right_width, lo, hi);
  c.lights_share = std::clamp(c.lights_share, 0.15f, 0.85f);
  c.material_share = std::clamp(c.material_share, 0.2f, 0.9f);
  c.outliner_share = std::clamp(c.outliner_share, 0.15f, 0.7f);
  // The panels shown share half the window: past it, the wider gives way first (down to the
  // narrower's width), then both alike; never below lo.
  const float budget = std::floor(width * 0.5f);
  float* l = c.left_collapsed ? nullptr : &c.left_width;
  float* r = c.right_collapsed ? nullptr : &c.right_width;
  const float strips = (l ? 0.0f : kStripWidth) + (r ? 0.0f : kStripWidth);
  float excess = (l ? *l : 0.0f) + (r ? *r : 0.0f) + strips - budget;
  if (excess <= 0.0f) return;
  if (l != nullptr && r != nullptr) {
    float* wider = *r >= *l ? r : l;
    float* narrower = wider == r ? l : r;
    const float first = std::min(excess, *wider - *narrower);
    *wider -= first;
    excess -= first;
    *wider -= excess * 0.5f;
    *narrower -= excess * 0.5f;
  } else if (l != nullptr || r != nullptr) {
    *(l != nullptr ? l : r) -= excess;
  }
  c.left_width = std::max(std::floor(c.left_width), lo);
  c.right_width = std::max(std::floor(c.right_width), lo);
}

PanelLayout panel_layout(const PanelChoices& choices, float width, float height, float menu_h,
                         float status_h) {
  PanelChoices c = choices;
  clamp_panel_widths(c, width);
  PanelLayout out;
  out.menu = {0, 0, width, menu_h};
  const float top = menu_h;
  const float body_h = std::max(height - menu_h - status_h, 1.0f);
  out.status = {0, top + body_h, width, status_h};
  out.left_width = c.left_width;
  out.right_width = c.right_width;
  if (c.viewport_maximised) {
    out.viewport = {0, top, width, body_h};
    return out;
  }
  float x0 = 0.0f, x1 = width;  // the viewport's left and right edges
  if (c.left_collapsed) {
    out.left_strip = {0, top, kStripWidth, body_h};
    x0 = kStripWidth;
  } else {
    const float material_h = std::floor(body_h * c.material_share);
    out.left = {0, top, c.left_width, material_h};
    out.reference = {0, top + material_h, c.left_width, body_h - material_h};
    out.material_split = {0, top + material_h - kSplitterWidth * 0.5f, c.left_width,
                          kSplitterWidth};
    x0 = c.left_width;
    out.left_split = {x0 - kSplitterWidth * 0.5f, top, kSplitterWidth, body_h};
  }
  if (c.right_collapsed) {
    out.right_strip = {width - kStripWidth, top, kStripWidth, body_h};
    x1 = width - kStripWidth;
  } else {
    x1 = width - c.right_width;
    const float outliner_h = std::floor(body_h * c.outliner_share);
    const float below = body_h - outliner_h;  // Lights & Scene over View & Quality
    const float lights_h = std::floor(below * c.lights_share);
    const float lights_y = top + outliner_h;
    out.outliner = {x1, top, c.right_width, outliner_h};
    out.lights = {x1, lights_y, c.right_width, lights_h};
    out.view = {x1, lights_y + lights_h, c.right_width, below - lights_h};
    out.right_split = {x1 - kSplitterWidth * 0.5f, top, kSplitterWidth, body_h};
    out.outliner_split = {x1, lights_y - kSplitterWidth * 0.5f, c.right_width, kSplitterWidth};
    out.lights_split = {x1, lights_y + lights_h - kSplitterWidth * 0.5f, c.right_width,
                        kSplitterWidth};
  }
  out.viewport = {x0, top, std::max(x1 - x0, 1.0f), body_h};
  return out;
}

}  // namespace gloss
