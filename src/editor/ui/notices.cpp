#include "editor/ui/notices.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>

namespace gloss {

namespace {
constexpr double kInfoSeconds = 6.0;
constexpr double kErrorSeconds = 12.0;
constexpr std::size_t kMaxShown = 5;
}  // namespace

void Notices::info(const std::string& text, double now_s) {
  items.push_back({text, false, now_s + kInfoSeconds});
  if (items.size() > kMaxShown) items.erase(items.begin());
  last = text;
}

void Notices::error(const std::string& text, double now_s) {
  items.push_back({text, true, now_s + kErrorSeconds});
  if (items.size() > kMaxShown) items.erase(items.begin());
  last = "error: " + text;
  std::fprintf(stderr, "gloss: error: %s\n", text.c_str());
}

double Notices::expire(double now_s) {
  items.erase(std::remove_if(items.begin(), items.end(),
                             [&](const Notice& n) { return n.until_s <= now_s; }),
              items.end());
  double next = -1.0;
  for (const Notice& n : items) {
    if (next < 0.0 || n.until_s - now_s < next) next = n.until_s - now_s;
  }
  return next;
}

void Notices::draw(float right, float bottom) const {
  if (items.empty()) return;
  ImGui::SetNextWindowPos(ImVec2(right - 12.0f, bottom - 12.0f), ImGuiCond_Always,
                          ImVec2(1.0f, 1.0f));
  ImGui::SetNextWindowBgAlpha(0.85f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoSavedSettings |
                                 ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
  if (!ImGui::Begin("##notices", nullptr, flags)) {
    ImGui::End();
    return;
  }
  for (const Notice& n : items) {
    const ImVec4 colour =
        n.error ? ImVec4(1.0f, 0.45f, 0.4f, 1.0f) : ImVec4(0.6f, 0.95f, 0.6f, 1.0f);
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 40.0f);
    ImGui::TextColored(colour, "%s", n.text.c_str());
    ImGui::PopTextWrapPos();
  }
  ImGui::End();
}

}  // namespace gloss
