// The lobe view's second material (lobe_overlay.h) and its script lines: the snapshot's material
// of the selected object, a document material or a preset by name, nothing for names that are
// not there.
#include "editor/model/view/lobe_overlay.h"

#include <gtest/gtest.h>

#include "editor/model/script/script.h"
#include "io/material/preset_table.h"
#include "support/test_scene.h"

namespace gloss {
namespace {

TEST(LobeOverlay, ResolvesTheSnapshotAMaterialOrAPreset) {
  const Scene scene = test::two_sphere_scene();
  ViewSettings view;
  EXPECT_FALSE(lobe_overlay_material(view, scene, 0, nullptr));  // none chosen
  Snapshot snapshot{scene, 3, "snapshot 1"};
  snapshot.scene.materials[static_cast<std::size_t>(scene.objects[1].material)].shininess = 7.0f;
  view.lobe_overlay = LobeOverlay::snapshot;
  EXPECT_FALSE(lobe_overlay_material(view, scene, 1, nullptr));  // no snapshot taken
  const auto from_snapshot = lobe_overlay_material(view, scene, 1, &snapshot);
  ASSERT_TRUE(from_snapshot);
  EXPECT_EQ(from_snapshot->material.shininess, 7.0f);  // the snapshot's, not the document's
  EXPECT_EQ(from_snapshot->label.rfind("snapshot 1: ", 0), 0u);
  EXPECT_FALSE(lobe_overlay_material(view, scene, 5, &snapshot));  // no such object

  view.lobe_overlay = LobeOverlay::material;
  view.lobe_overlay_name = scene.material_names.back();
  const auto named = lobe_overlay_material(view, scene, 0, nullptr);
  ASSERT_TRUE(named);
  EXPECT_EQ(named->material.diffuse, scene.materials.back().diffuse);
  view.lobe_overlay_name = "no such material";
  EXPECT_FALSE(lobe_overlay_material(view, scene, 0, nullptr));

  view.lobe_overlay = LobeOverlay::preset;
  view.lobe_overlay_name = "emerald";
  const auto preset = lobe_overlay_material(view, scene, 0, nullptr);
  ASSERT_TRUE(preset);
  EXPECT_EQ(preset->material.diffuse, find_preset("emerald")->material.diffuse);
  EXPECT_EQ(preset->label, "preset 'emerald'");
}

TEST(LobeOverlay, ScriptLinesParseAndRefuseUnknownNames) {
  const Script s = parse_script(
      "lobe plot albedo\nlobe plot 3d\nlobe overlay preset gold\nlobe overlay none\n"
      "lobe turn 20 60\n",
      "lobe.txt");
  ASSERT_EQ(s.lines.size(), 5u);
  EXPECT_EQ(std::get<LobeAction>(s.lines[0].action).plot, LobePlot::albedo);
  EXPECT_EQ(std::get<LobeAction>(s.lines[1].action).plot, LobePlot::hemisphere);
  EXPECT_EQ(std::get<LobeAction>(s.lines[2].action).overlay, LobeOverlay::preset);
  EXPECT_EQ(std::get<LobeAction>(s.lines[2].action).name, "gold");
  EXPECT_EQ(std::get<LobeAction>(s.lines[3].action).overlay, LobeOverlay::none);
  EXPECT_EQ(std::get<LobeAction>(s.lines[4].action).tilt_deg, 60.0f);
  EXPECT_THROW(parse_script("lobe plot polar\n", "bad.txt"), std::exception);
  EXPECT_THROW(parse_script("lobe overlay preset tin\n", "bad.txt"), std::exception);
  EXPECT_THROW(parse_script("lobe turn 0 95\n", "bad.txt"), std::exception);
}

}  // namespace
}  // namespace gloss
