// The window's layout rules (panel_layout.h, pane_layout.h, text_fit.h) as numbers: at a
// laptop's 1024 x 640 the viewport keeps at least half the width, collapsed panels are strips,
// the maximised viewport takes the whole width, several panes fill the viewport, long status
// messages are cut in the middle.
#include <gtest/gtest.h>

#include "editor/model/layout/pane_layout.h"
#include "editor/model/layout/panel_layout.h"
#include "editor/model/layout/text_fit.h"

namespace gloss {
namespace {

constexpr float kMenu = 19.0f, kStatus = 25.0f;  // the bars' heights at ImGui's default font

TEST(PanelLayout, AtLaptopSizeTheViewportKeepsHalfTheWidth) {
  const PanelLayout l = panel_layout(PanelChoices{}, 1024, 640, kMenu, kStatus);
  // Defaults: a quarter of 1024 = 256 each side, so 1024 - 512 = 512 for the viewport.
  EXPECT_EQ(l.left.w, 256.0f);
  EXPECT_EQ(l.lights.w, 256.0f);
  EXPECT_EQ(l.viewport.x, 256.0f);
  EXPECT_EQ(l.viewport.w, 512.0f);
  EXPECT_GE(l.viewport.w, 512.0f);
  EXPECT_EQ(l.viewport.y, kMenu);
  EXPECT_EQ(l.viewport.h, 640.0f - kMenu - kStatus);
  EXPECT_EQ(l.status.y, 640.0f - kStatus);
  // The Outliner on top (floor(596 x 0.4) = 238), then Lights & Scene over View & Quality,
  // half each of the 358 left, the column's full height; Material on top of Reference (two
  // thirds, floor(596 x 0.66) = 393), likewise.
  EXPECT_EQ(l.outliner.y, kMenu);
  EXPECT_EQ(l.outliner.h, 238.0f);
  EXPECT_EQ(l.lights.y, l.outliner.bottom());
  EXPECT_EQ(l.lights.h, 179.0f);
  EXPECT_EQ(l.view.y, l.lights.bottom());
  EXPECT_EQ(l.outliner.h + l.lights.h + l.view.h, l.viewport.h);
  EXPECT_EQ(l.left.h, 393.0f);
  EXPECT_EQ(l.reference.y, l.left.bottom());
  EXPECT_EQ(l.left.h + l.reference.h, l.viewport.h);
}

TEST(PanelLayout, DraggedPanelsNeverTakeMoreThanHalf) {
  // Both dragged to 40% (410 px) at 1024: the panels' 820 px exceed half (512) by 308, shared
  // equally: 256 each, the viewport 512.
  PanelChoices c;
  c.left_width = 600;  // past 40%: 409
  c.right_width = 410;
  const PanelLayout l = panel_layout(c, 1024, 640, kMenu, kStatus);
  EXPECT_EQ(l.left.w + l.lights.w, 512.0f);
  EXPECT_EQ(l.viewport.w, 512.0f);
  // The wider gives way first: 300 and 250 become 262 and 250 (sum 512).
  c.left_width = 300;
  c.right_width = 250;
  const PanelLayout k = panel_layout(c, 1024, 640, kMenu, kStatus);
  EXPECT_EQ(k.left.w, 262.0f);
  EXPECT_EQ(k.lights.w, 250.0f);
  // At 1600 x 1000 the defaults are 380 each (a quarter, at most 380): nothing taken away.
  const PanelLayout big = panel_layout(PanelChoices{}, 1600, 1000, kMenu, kStatus);
  EXPECT_EQ(big.left.w, 380.0f);
  EXPECT_EQ(big.viewport.w, 1600.0f - 2 * 380.0f);
}

TEST(PanelLayout, CollapsedPanelsAreStripsAndGiveTheirRoomToTheViewport) {
  PanelChoices c;
  c.left_collapsed = true;
  PanelLayout l = panel_layout(c, 1024, 640, kMenu, kStatus);
  EXPECT_FALSE(l.left.visible());
  EXPECT_FALSE(l.reference.visible());
  EXPECT_FALSE(l.left_split.visible());
  EXPECT_EQ(l.left_strip.w, kStripWidth);
  EXPECT_EQ(l.viewport.x, kStripWidth);
  EXPECT_EQ(l.viewport.w, 1024.0f - kStripWidth - 256.0f);
  c.right_collapsed = true;
  l = panel_layout(c, 1024, 640, kMenu, kStatus);
  EXPECT_FALSE(l.outliner.visible());
  EXPECT_FALSE(l.lights.visible());
  EXPECT_FALSE(l.view.visible());
  EXPECT_EQ(l.right_strip.x, 1024.0f - kStripWidth);
  EXPECT_EQ(l.viewport.w, 1024.0f - 2 * kStripWidth);
  // Expanding again restores the width the panel had.
  c.left_collapsed = false;
  c.left_width = 300;
  l = panel_layout(c, 1024, 640, kMenu, kStatus);
  EXPECT_EQ(l.left.w, 300.0f);
}

TEST(PanelLayout, TheMaximisedViewportTakesTheWholeWidth) {
  PanelChoices c;
  c.viewport_maximised = true;
  const PanelLayout l = panel_layout(c, 1024, 640, kMenu, kStatus);
  EXPECT_EQ(l.viewport.x, 0.0f);
  EXPECT_EQ(l.viewport.w, 1024.0f);
  EXPECT_FALSE(l.left.visible());
  EXPECT_FALSE(l.left_strip.visible());
  EXPECT_FALSE(l.right_strip.visible());
  EXPECT_FALSE(l.right_split.visible());
}

TEST(PanelLayout, SplittersAreSeveralPixelsWideOnTheBorders) {
  const PanelLayout l = panel_layout(PanelChoices{}, 1024, 640, kMenu, kStatus);
  EXPECT_EQ(l.left_split.w, kSplitterWidth);
  EXPECT_GE(kSplitterWidth, 6.0f);
  EXPECT_EQ(l.left_split.x + l.left_split.w * 0.5f, l.left.right());
  EXPECT_EQ(l.right_split.x + l.right_split.w * 0.5f, l.lights.x);
  EXPECT_EQ(l.outliner_split.y + l.outliner_split.h * 0.5f, l.outliner.bottom());
  EXPECT_EQ(l.lights_split.y + l.lights_split.h * 0.5f, l.lights.bottom());
  EXPECT_EQ(l.material_split.y + l.material_split.h * 0.5f, l.left.bottom());
}

TEST(PaneLayout, TermsFillTheViewportWithTheArrangementOfLargestFrames) {
  // The viewport at 1024 x 640 (512 x 596), a 4:3 document: 2 x 2 cells of 256 x 298 hold a
  // 256 x 192 frame; 4 in a row 128 x 96; 4 in a column (512 x 149 cells) 198 x 149.
  const LayoutRect area{256, 19, 512, 596};
  const PaneArrangement t = arrange_panes(ViewMode::terms, area, 4.0f / 3.0f);
  EXPECT_EQ(t.count, 4);
  EXPECT_EQ(t.columns, 2);
  EXPECT_TRUE(t.fill);
  EXPECT_EQ(t.panes[0].w, 256.0f);
  EXPECT_EQ(t.panes[0].h, 298.0f);
  EXPECT_EQ(t.frames[0].w, 256.0f);
  EXPECT_EQ(t.frames[0].h, 192.0f);
  EXPECT_EQ(t.frames[0].y, t.panes[0].y + 53.0f);  // centred: (298 - 192) / 2
  EXPECT_EQ(t.panes[1].x, t.panes[0].right());     // panes touch
  EXPECT_EQ(t.panes[2].y, t.panes[0].bottom());
  EXPECT_EQ(empty_share(t, area), 0.0f);  // no band
  // A wide, short viewport (1550 x 300): four in a row, frames 387 x 290 instead of 2 x 2's
  // 200 x 150; 2 columns of rounding left over.
  const LayoutRect wide{0, 0, 1550, 300};
  const PaneArrangement w = arrange_panes(ViewMode::terms, wide, 4.0f / 3.0f);
  EXPECT_EQ(w.columns, 4);
  EXPECT_EQ(w.frames[0].w, 387.0f);
  EXPECT_EQ(w.frames[0].h, 290.0f);
  EXPECT_LT(empty_share(w, wide), 0.002f);
}

TEST(PaneLayout, AbPutsTheLegendBesideItsThreeImages) {
  // 512 x 596: a column of three with the legend to the right (302 x 198 cells, 264 x 198
  // frames) beats 2 x 2 with the legend in the fourth cell (256 x 192 frames).
  const LayoutRect area{256, 19, 512, 596};
  const PaneArrangement ab = arrange_panes(ViewMode::ab, area, 4.0f / 3.0f);
  EXPECT_EQ(ab.count, 3);
  EXPECT_EQ(ab.columns, 1);
  EXPECT_EQ(ab.panes[0].w, 302.0f);
  EXPECT_EQ(ab.frames[0].w, 264.0f);
  EXPECT_EQ(ab.frames[0].h, 198.0f);
  EXPECT_EQ(ab.legend.x, ab.panes[0].right());
  EXPECT_EQ(ab.legend.w, kLegendWidth);
  EXPECT_LT(empty_share(ab, area), 0.01f);
  // A squarer viewport (800 x 700): 2 x 2 (400 x 350 cells, 400 x 300 frames) with the legend in
  // the fourth cell, beside the heat map and under B.
  const LayoutRect square{0, 0, 800, 700};
  const PaneArrangement q = arrange_panes(ViewMode::ab, square, 4.0f / 3.0f);
  EXPECT_EQ(q.columns, 2);
  EXPECT_EQ(q.frames[0].w, 400.0f);
  EXPECT_EQ(q.legend.x, q.panes[1].x);
  EXPECT_EQ(q.legend.y, q.panes[2].y);
  EXPECT_EQ(empty_share(q, square), 0.0f);
  // Wide and short (1200 x 330): a row beside the legend, (1200 - 210) / 3 = 330 wide cells.
  const LayoutRect wide{0, 0, 1200, 330};
  const PaneArrangement row = arrange_panes(ViewMode::ab, wide, 4.0f / 3.0f);
  EXPECT_EQ(row.columns, 3);
  EXPECT_EQ(row.panes[0].w, 330.0f);
  EXPECT_EQ(row.frames[0].h, 247.0f);
  EXPECT_EQ(row.legend.x, row.panes[2].right());
  // No pane overlaps the legend.
  for (const PaneArrangement* a : {&ab, &q, &row}) {
    for (int i = 0; i < a->count; ++i) {
      const LayoutRect& p = a->panes[i];
      const bool apart = p.right() <= a->legend.x || a->legend.right() <= p.x ||
                         p.bottom() <= a->legend.y || a->legend.bottom() <= p.y;
      EXPECT_TRUE(apart) << i;
    }
  }
}

TEST(PaneLayout, TheRenderViewKeepsTheDocumentsAspect) {
  const LayoutRect area{256, 19, 512, 596};
  const PaneArrangement r = arrange_panes(ViewMode::render, area, 4.0f / 3.0f);
  EXPECT_EQ(r.count, 1);
  EXPECT_FALSE(r.fill);
  EXPECT_EQ(r.panes[0].w, 512.0f);
  EXPECT_EQ(r.panes[0].h, 384.0f);
  EXPECT_EQ(r.panes[0].y, 19.0f + 106.0f);  // centred
}

TEST(TextFit, LongTextKeepsItsStartAndItsEnd) {
  const TextWidth mono = [](const std::string& s) { return 7.0f * static_cast<float>(s.size()); };
  EXPECT_EQ(fit_text("saved screenshot a.png", 500.0f, mono), "saved screenshot a.png");
  // 20 characters of room: 17 beside the dots, 5 of them (a third) from the end.
  const std::string cut = fit_text("saved screenshot /home/user/shots/gloss-1.png", 140.0f, mono);
  EXPECT_EQ(cut, "saved screen...1.png");
  EXPECT_LE(mono(cut), 140.0f);
  EXPECT_EQ(fit_text("anything", 14.0f, mono), "");  // not even the dots
  // UTF-8 characters are never cut in two: "é" is two bytes.
  const std::string accents =
      fit_text("\xC3\xA9\xC3\xA9\xC3\xA9\xC3\xA9\xC3\xA9\xC3\xA9", 35.0f, [](const std::string& s) {
        float n = 0;
        for (char ch : s) n += (ch & 0xC0) == 0x80 ? 0.0f : 7.0f;
        return n;
      });
  EXPECT_EQ(accents, "\xC3\xA9\xC3\xA9...");
}

}  // namespace
}  // namespace gloss
