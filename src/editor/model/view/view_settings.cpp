#include "editor/model/view/view_settings.h"

namespace gloss {

namespace {

template <class E, std::size_t N>
bool parse_name(const std::string& name, const E (&values)[N], E& out) {
  for (E value : values) {
    if (name == to_string(value)) {
      out = value;
      return true;
    }
  }
  return false;
}

}  // namespace

const char* to_string(ViewMode mode) {
  switch (mode) {
    case ViewMode::render:
      return "render";
    case ViewMode::terms:
      return "terms";
    case ViewMode::single:
      return "single";
    case ViewMode::ab:
      return "ab";
    case ViewMode::lobe:
      return "lobe";
  }
  return "?";
}

bool parse_view_mode(const std::string& name, ViewMode& mode) {
  const ViewMode all[] = {ViewMode::render, ViewMode::terms, ViewMode::single, ViewMode::ab,
                          ViewMode::lobe};
  return parse_name(name, all, mode);
}

const char* to_string(TermView term) {
  switch (term) {
    case TermView::emissive_ambient:
      return "emissive+ambient";
    case TermView::emissive:
      return "emissive";
    case TermView::ambient:
      return "ambient";
    case TermView::diffuse:
      return "diffuse";
    case TermView::specular:
      return "specular";
    case TermView::total:
      return "total";
  }
  return "?";
}

const char* display_name(TermView term) {
  return term == TermView::emissive_ambient ? "emissive + ambient" : to_string(term);
}

bool parse_term_view(const std::string& name, TermView& term) {
  const TermView all[] = {TermView::emissive_ambient, TermView::emissive, TermView::ambient,
                          TermView::diffuse,          TermView::specular, TermView::total};
  return parse_name(name, all, term);
}

const char* to_string(ScreenshotKind kind) {
  switch (kind) {
    case ScreenshotKind::viewport:
      return "viewport";
    case ScreenshotKind::terms:
      return "terms";
    case ScreenshotKind::window:
      return "window";
    case ScreenshotKind::shown:
      return "shown";
    case ScreenshotKind::exr:
      return "exr";
  }
  return "?";
}

bool parse_screenshot_kind(const std::string& name, ScreenshotKind& kind) {
  const ScreenshotKind all[] = {ScreenshotKind::viewport, ScreenshotKind::terms,
                                ScreenshotKind::window, ScreenshotKind::shown,
                                ScreenshotKind::exr};
  return parse_name(name, all, kind);
}

const char* to_string(LobePlot plot) {
  switch (plot) {
    case LobePlot::plane:
      return "plane";
    case LobePlot::hemisphere:
      return "3d";
    case LobePlot::albedo:
      return "albedo";
  }
  return "?";
}

bool parse_lobe_plot(const std::string& name, LobePlot& plot) {
  const LobePlot all[] = {LobePlot::plane, LobePlot::hemisphere, LobePlot::albedo};
  return parse_name(name, all, plot);
}

bool lobe_energy_normalize(LobeEnergy energy, bool document_setting) {
  return energy == LobeEnergy::scene ? document_setting : energy == LobeEnergy::on;
}

}  // namespace gloss
