#pragma once
// Where the window's parts sit (editor/ui/layout.cpp draws them there): the menu bar on top, the
// status bar below, the Material and Reference panels in a column on the left, the Outliner, the
// Lights & Scene and View & Quality panels in a column on the right, the viewport between.
// GL-free, so the rules
// are tested as numbers:
//   - the viewport keeps at least half the window's width: the side panels share the other half
//     (each between kMinPanelWidth, or a quarter of the window when that is less, and 40% of it);
//   - a collapsed panel is a strip of kStripWidth pixels with its name, which expands it again;
//   - a maximised viewport takes the whole width, panels and strips hidden;
//   - splitters are kSplitterWidth pixels wide, centred on the borders they move.
// Pixels are the window's (ImGui's screen units), y down.
namespace gloss {

constexpr float kMinPanelWidth = 220.0f;  // a panel narrower than this wraps its rows
constexpr float kStripWidth = 24.0f;      // a collapsed panel
constexpr float kSplitterWidth = 8.0f;    // what a user grabs to resize, centred on the border

// What the user chose: sizes dragged to (0: the default share of the window), collapsed panels,
// the maximised viewport. lights_share: the Lights panel's part of the right column's height;
// material_share: the Material panel's part of the left column's (the Reference panel's the rest);
// outliner_share: the Outliner's part of the right column's, at its top (lights_share is then a
// part of what it leaves).
struct PanelChoices {
  float left_width = 0.0f, right_width = 0.0f, lights_share = 0.5f, material_share = 0.66f;
  float outliner_share = 0.4f;
  bool left_collapsed = false, right_collapsed = false;
  bool viewport_maximised = false;
};

struct LayoutRect {
  float x = 0, y = 0, w = 0, h = 0;
  bool visible() const { return w > 0.0f && h > 0.0f; }
  float right() const { return x + w; }
  float bottom() const { return y + h; }
};

struct PanelLayout {
  LayoutRect menu, status;
  LayoutRect left, reference;             // panels (left: Material); zero-sized when hidden
  LayoutRect outliner, lights, view;      // the right column, top to bottom
  LayoutRect left_strip, right_strip;     // strips of collapsed panels; zero-sized otherwise
  LayoutRect viewport;                    // the image's area
  LayoutRect left_split, right_split;     // vertical splitters; zero-sized when not shown
  LayoutRect outliner_split;              // between the Outliner and Lights & Scene
  LayoutRect lights_split;                // between Lights & Scene and View & Quality
  LayoutRect material_split;              // between Material and Reference
  float left_width = 0, right_width = 0;  // the widths in use (choices clamped)
};

// The layout of a window width x height with menu and status bars of the given heights.
PanelLayout panel_layout(const PanelChoices& choices, float width, float height, float menu_h,
                         float status_h);

// The widths the choices keep within the rules above for a window this wide (what layout uses);
// a splitter drag adds to a width and then clamps it here, so the viewport never loses its half.
void clamp_panel_widths(PanelChoices& choices, float width);

}  // namespace gloss
