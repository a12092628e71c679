#pragma once
// The lobe view's plots beside the plane of incidence (lobe_view.cpp): the lobe over the whole
// hemisphere of outgoing directions in 3D (lobe_hemisphere.cpp) and the directional albedo
// against the incidence angle (lobe_albedo.cpp). Private to the viewport.
#include <optional>
#include <string>

#include <imgui.h>

#include "analysis/lobe/directional_albedo.h"
#include "editor/model/view/albedo_curves.h"
#include "editor/model/view/lobe_overlay.h"
#include "editor/model/view/view_settings.h"
#include "scene/material.h"

namespace gloss {

// What the lobe view shows, resolved once per frame: the selected material and the exponents
// each model gets (the 4x rule), the normalisation, the light, and the second material.
struct LobeSubject {
  Material material;
  std::string name;                          // the material's name
  AlbedoParams params;                       // exponents of both models, normalisation
  ShadingModel model = ShadingModel::phong;  // the scene's
  double elevation_deg = 45;                 // the light above the surface
  std::optional<OverlayMaterial> overlay;
  AlbedoParams overlay_params;  // the overlay's exponents by the same rule
};

// Colours the plots share.
constexpr ImU32 kLobeText = IM_COL32(225, 225, 225, 255);
constexpr ImU32 kLobeDim = IM_COL32(150, 150, 158, 255);
constexpr ImU32 kLobeGrid = IM_COL32(62, 62, 70, 255);
constexpr ImU32 kLobeFloor = IM_COL32(130, 205, 130, 255);
constexpr ImU32 kLobePhong = IM_COL32(255, 150, 40, 255);
constexpr ImU32 kLobeBlinn = IM_COL32(80, 190, 255, 255);
constexpr ImU32 kLobeLight = IM_COL32(255, 225, 80, 255);
constexpr ImU32 kLobeOverlay = IM_COL32(235, 110, 235, 255);

// lobe_controls.cpp: the first row of controls (light elevation, normalisation, radius scale, 4x
// rule); the second (which plot, which second material; snapshot may be null); the exponents
// each model's curve gets (the scene's model keeps the material's, the other the rescaled one
// when the highlight size is kept, document.h) and the normalisation.
void draw_lobe_controls(ViewSettings& view, bool document_energy);
void draw_lobe_plot_controls(ViewSettings& view, const Scene& scene, const Snapshot* snapshot,
                             const std::optional<OverlayMaterial>& overlay);
AlbedoParams lobe_exponents(const Material& m, const Scene& scene, const ViewSettings& view);

// A dashed line segment (the overlay's curves, the mirror direction).
void lobe_dashed_line(ImDrawList* list, ImVec2 a, ImVec2 b, ImU32 colour, float thickness);

// The 3D lobe in pos/size: the radiance towards every outgoing direction as a surface (rings of
// equal elevation and meridians), the surface disc, the normal, the light and the mirror
// direction; the overlay's lobe in its colour. Dragging in it turns the view (view's azimuth and
// tilt). Returns the height used by the legend under it.
void draw_lobe_hemisphere(const LobeSubject& subject, ViewSettings& view, ImVec2 pos, ImVec2 size);

// The directional albedo plot in pos/size: per model the share of a unit directional light's
// irradiance the material sends into the hemisphere, against the incidence angle, with the
// quadrature's stated error; the overlay's dashed; the light's incidence marked.
void draw_lobe_albedo(const LobeSubject& subject, AlbedoCurves& curves,
                      AlbedoCurves& overlay_curves, ImVec2 pos, ImVec2 size);

}  // namespace gloss
