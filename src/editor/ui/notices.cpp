#include "editor/ui/notices.h"

#include <algorithm>
#include <cmath>
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

void Notices::draw(float right, float y, bool from_top) const {
  if (items.empty()) return;
  // The window's size from the wrapped texts themselves: an auto-resized window takes its size
  // from the frame before, and a screenshot of the frame a notice arrived cut its last line.
  const ImGuiStyle& style = ImGui::GetStyle();
  const float wrap = ImGui::GetFontSize() * 40.0f;
  ImVec2 content(0.0f, 0.0f);
  for (const Notice& n : items) {
    const ImVec2 size = ImGui::CalcTextSize(n.text.c_str(), nullptr, false, wrap);
    content.x = std::max(content.x, std::ceil(size.x) + 1.0f);  // no wrap from rounding
    content.y += size.y + (content.y > 0.0f ? style.ItemSpacing.y : 0.0f);
  }
  ImGui::SetNextWindowPos(ImVec2(right - 12.0f, y), ImGuiCond_Always,
                          ImVec2(1.0f, from_top ? 0.0f : 1.0f));
  ImGui::SetNextWindowSize(
      ImVec2(content.x + 2.0f * style.WindowPadding.x, content.y + 2.0f * style.WindowPadding.y));
  ImGui::SetNextWindowBgAlpha(0.85f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoInputs |
                                 ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
  if (!ImGui::Begin("##notices", nullptr, flags)) {
    ImGui::End();
    return;
  }
  for (const Notice& n : items) {
    const ImVec4 colour =
        n.error ? ImVec4(1.0f, 0.45f, 0.4f, 1.0f) : ImVec4(0.6f, 0.95f, 0.6f, 1.0f);
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + wrap);
    ImGui::TextColored(colour, "%s", n.text.c_str());
    ImGui::PopTextWrapPos();
  }
  ImGui::End();
}

}  // namespace gloss
