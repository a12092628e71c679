#include "editor/ui/panels/map_slots.h"

#include <cstdint>
#include <filesystem>

#include <imgui.h>

#include "editor/ui/file_browser.h"
#include "editor/ui/panels/map_thumbnails.h"
#include "editor/ui/panels/panel_widgets.h"
#include "editor/ui/parts/commands.h"
#include "scene/fields/fields.h"

namespace gloss {

namespace {

void set_map(Commands& commands, int object, MapSlot slot, const TextureMap& map) {
  commands.execute(SetField{FieldPart::material, object, map_key(slot), map_value(map)});
}

// One slot's row: thumbnail, name and file, then Load... / Clear and, for a map, its scale.
void draw_slot(Commands& commands, FileBrowser& browser, MapThumbnails& thumbnails, int object,
               MapSlot slot, const TextureMap& map, const std::string& start_folder) {
  ImGui::PushID(static_cast<int>(slot));
  const float side = 2.0f * ImGui::GetTextLineHeightWithSpacing();
  if (GLuint id = thumbnails.get(map.texture, is_colour_map(slot)); id != 0) {
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(id)), ImVec2(side, side));
    if (ImGui::IsItemHovered()) {
      const Texture& t = *map.texture;
      ImGui::SetTooltip("%s\n%d x %d, %s %d-bit%s, %d levels", map.file.c_str(), t.width(),
                        t.height(), t.format.c_str(), t.bits,
                        t.srgb_decoded ? ", sRGB-decoded" : ", linear", t.level_count());
    }
  } else {
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImGui::GetWindowDrawList()->AddRect(at, ImVec2(at.x + side, at.y + side),
                                        ImGui::GetColorU32(ImGuiCol_Border));
    ImGui::Dummy(ImVec2(side, side));
  }
  ImGui::SameLine();
  ImGui::BeginGroup();
  const std::string name = map.named() ? std::filesystem::path(map.file).filename().string() : "";
  ImGui::Text("%-9s %s", to_string(slot), map.named() ? name.c_str() : "(none)");
  if (ImGui::SmallButton("Load...")) {
    browser.map_target.object = object;
    browser.map_target.slot = slot;
    browser.show(BrowsePurpose::load_map, start_folder, "");
  }
  if (map.named()) {
    ImGui::SameLine();
    if (ImGui::SmallButton("Clear")) set_map(commands, object, slot, TextureMap{});
    ImGui::SameLine();
    // Applied on Enter: one command (one undo step) per scale typed, not one per keystroke.
    float scale[2] = {map.scale.x, map.scale.y};
    // Labelled: two bare numbers beside Load and Clear did not say what they are.
    ImGui::SetNextItemWidth(
        -(ImGui::CalcTextSize("scale").x + ImGui::GetStyle().ItemInnerSpacing.x));
    if (ImGui::InputFloat2("scale", scale, "%.3g", ImGuiInputTextFlags_EnterReturnsTrue)) {
      TextureMap scaled = map;
      scaled.scale = glm::vec2(scale[0], scale[1]);
      set_map(commands, object, slot, scaled);
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("(u, v) scale of this map: Enter applies");
  }
  ImGui::EndGroup();
  ImGui::PopID();
}

}  // namespace

void draw_map_slots(Commands& commands, FileBrowser& browser, MapThumbnails& thumbnails, int object,
                    const Material& material, const std::string& start_folder) {
  section_title("Maps");
  for (int s = 0; s < kMapSlots; ++s) {
    const auto slot = static_cast<MapSlot>(s);
    draw_slot(commands, browser, thumbnails, object, slot, material.map(slot), start_folder);
  }
  thumbnails.prune();
}

}  // namespace gloss
