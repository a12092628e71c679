#include "editor/model/layout/pane_layout.h"

#include <algorithm>
#include <cmath>

namespace gloss {

namespace {

// Where the legend goes relative to the image grid.
enum class Legend { none, right, below, cell };

struct Candidate {
  int columns = 1, rows = 1;
  Legend legend = Legend::none;
};

// The largest whole-pixel rectangle of aspect in w x h, centred in it.
LayoutRect frame_in(const LayoutRect& cell, float aspect) {
  float fw = std::floor(std::min(cell.w, cell.h * aspect));
  float fh = std::floor(fw / aspect);
  if (fw < 1.0f || fh < 1.0f) fw = fh = 0.0f;
  return {cell.x + std::floor((cell.w - fw) * 0.5f), cell.y + std::floor((cell.h - fh) * 0.5f), fw,
          fh};
}

// The grid of c filling area (less the legend's room), count cells used.
PaneArrangement place(const Candidate& c, int count, const LayoutRect& area, float aspect) {
  float w = area.w, h = area.h;
  if (c.legend == Legend::right) w -= kLegendWidth;
  if (c.legend == Legend::below) h -= kLegendHeight;
  const float cell_w = std::floor(std::max(w, 0.0f) / static_cast<float>(c.columns));
  const float cell_h = std::floor(std::max(h, 0.0f) / static_cast<float>(c.rows));
  PaneArrangement out;
  out.count = count;
  out.columns = c.columns;
  out.rows = c.rows;
  out.fill = true;
  // The grid is centred: what rounding leaves over is split on both sides.
  const float grid_w = cell_w * static_cast<float>(c.columns);
  const float grid_h = cell_h * static_cast<float>(c.rows);
  const float legend_w = c.legend == Legend::right ? kLegendWidth : 0.0f;
  const float legend_h = c.legend == Legend::below ? kLegendHeight : 0.0f;
  const float x0 = area.x + std::floor((area.w - grid_w - legend_w) * 0.5f);
  const float y0 = area.y + std::floor((area.h - grid_h - legend_h) * 0.5f);
  for (int i = 0; i < count; ++i) {
    out.panes[i] = {x0 + static_cast<float>(i % c.columns) * cell_w,
                    y0 + static_cast<float>(i / c.columns) * cell_h, cell_w, cell_h};
    out.frames[i] = frame_in(out.panes[i], aspect);
  }
  switch (c.legend) {
    case Legend::right:
      out.legend = {x0 + grid_w, y0, kLegendWidth, grid_h};
      break;
    case Legend::below:
      out.legend = {x0, y0 + grid_h, grid_w, kLegendHeight};
      break;
    case Legend::cell:
      out.legend = {x0 + cell_w, y0 + cell_h, cell_w, cell_h};
      // The fourth cell must hold the legend: short of room, this arrangement is out.
      if (cell_w < kLegendWidth || cell_h < kLegendHeight) out.frames[0] = LayoutRect{};
      break;
    case Legend::none:
      break;
  }
  return out;
}

float frame_area(const PaneArrangement& a) {
  return a.frames[0].w * a.frames[0].h;
}

template <std::size_t N>
PaneArrangement best_of(const Candidate (&options)[N], int count, const LayoutRect& area,
                        float aspect) {
  PaneArrangement best = place(options[0], count, area, aspect);
  for (const Candidate& c : options) {
    const PaneArrangement a = place(c, count, area, aspect);
    if (frame_area(a) > frame_area(best)) best = a;
  }
  return best;
}

}  // namespace

PaneArrangement arrange_panes(ViewMode mode, const LayoutRect& area, float aspect) {
  aspect = aspect > 0.0f ? aspect : 1.0f;
  if (mode == ViewMode::terms) {
    const Candidate options[] = {{2, 2}, {4, 1}, {1, 4}};
    return best_of(options, 4, area, aspect);
  }
  if (mode == ViewMode::ab) {
    const Candidate options[] = {{2, 2, Legend::cell},
                                 {3, 1, Legend::below},
                                 {3, 1, Legend::right},
                                 {1, 3, Legend::right},
                                 {1, 3, Legend::below}};
    return best_of(options, 3, area, aspect);
  }
  // One pane in the document's aspect, centred: the render as exports hold it.
  PaneArrangement one;
  one.panes[0] = one.frames[0] = frame_in(area, aspect);
  return one;
}

float empty_share(const PaneArrangement& a, const LayoutRect& area) {
  if (!area.visible()) return 0.0f;
  float used = a.legend.w * a.legend.h;
  for (int i = 0; i < a.count; ++i) used += a.panes[i].w * a.panes[i].h;
  return std::clamp(1.0f - used / (area.w * area.h), 0.0f, 1.0f);
}

}  // namespace gloss
