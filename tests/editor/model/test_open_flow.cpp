// Opening files in the editor: the save / discard / cancel question before unsaved edits would be
// dropped (unsaved_guard.h), and recent files kept per kind so the Add model panel offers models
// only (recent_files.h).
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "editor/model/session/recent_files.h"
#include "editor/model/session/unsaved_guard.h"
#include "support/scratch_folder.h"

namespace gloss {
namespace {

TEST(UnsavedGuard, ACleanDocumentOpensAtOnce) {
  UnsavedGuard guard;
  EXPECT_TRUE(guard.request_open("b.json", false));
  EXPECT_FALSE(guard.asking());
}

TEST(UnsavedGuard, UnsavedEditsAskAndEachAnswerDoesWhatItSays) {
  UnsavedGuard guard;
  EXPECT_FALSE(guard.request_open("b.json", true));
  EXPECT_TRUE(guard.asking());
  EXPECT_EQ(guard.waiting_path(), "b.json");
  const UnsavedGuard::Outcome save = guard.answer(UnsavedAnswer::save);
  EXPECT_FALSE(guard.asking());
  EXPECT_TRUE(save.save_first);
  EXPECT_TRUE(save.open);
  EXPECT_EQ(save.path, "b.json");

  EXPECT_FALSE(guard.request_open("c.json", true));
  const UnsavedGuard::Outcome discard = guard.answer(UnsavedAnswer::discard);
  EXPECT_FALSE(discard.save_first);
  EXPECT_TRUE(discard.open);
  EXPECT_EQ(discard.path, "c.json");

  EXPECT_FALSE(guard.request_open("d.json", true));
  const UnsavedGuard::Outcome cancel = guard.answer(UnsavedAnswer::cancel);
  EXPECT_FALSE(cancel.save_first);
  EXPECT_FALSE(cancel.open);
  EXPECT_FALSE(guard.asking());
  EXPECT_EQ(guard.waiting_path(), "");
}

TEST(UnsavedGuard, AnAnswerWithoutAQuestionDoesNothing) {
  UnsavedGuard guard;
  const UnsavedGuard::Outcome outcome = guard.answer(UnsavedAnswer::discard);
  EXPECT_FALSE(outcome.open);
  EXPECT_FALSE(outcome.save_first);
}

TEST(RecentLists, ScenesAndModelsAreKeptApart) {
  ScratchFolder folder;
  RecentLists lists;
  lists.of(RecentKind::scene).add("/data/room.json");
  lists.of(RecentKind::model).add("/data/cup.obj");
  lists.of(RecentKind::materials).add("/data/metals.json");
  EXPECT_EQ(lists.scenes.paths, std::vector<std::string>{"/data/room.json"});
  EXPECT_EQ(lists.models.paths, std::vector<std::string>{"/data/cup.obj"});
  EXPECT_EQ(lists.materials.paths, std::vector<std::string>{"/data/metals.json"});
  for (RecentKind kind : {RecentKind::scene, RecentKind::model, RecentKind::materials}) {
    save_recent_files(lists.of(kind), folder.path() / recent_file_name(kind));
  }
  const RecentLists back = load_recent_lists(folder.path());
  EXPECT_EQ(back.scenes.paths, std::vector<std::string>{"/data/room.json"});
  EXPECT_EQ(back.models.paths, std::vector<std::string>{"/data/cup.obj"});
  EXPECT_EQ(back.materials.paths, std::vector<std::string>{"/data/metals.json"});
  EXPECT_EQ(folder.entries(),
            (std::vector<std::string>{"recent-materials.txt", "recent-models.txt", "recent.txt"}));
}

TEST(RecentLists, TheScenesFileKeepsItsOldName) {
  ScratchFolder folder;
  std::ofstream(folder.file("recent.txt")) << "/data/old.json\n";
  const RecentLists lists = load_recent_lists(folder.path());
  EXPECT_EQ(lists.scenes.paths, std::vector<std::string>{"/data/old.json"});
  EXPECT_TRUE(lists.models.paths.empty());
}

}  // namespace
}  // namespace gloss
