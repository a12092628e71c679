// Where the file panel starts (issue 24, item 3): never in the shipped assets for a save; the
// user's last folder, else the XDG documents folder; names from the scene or material. And the
// user's material library folder.
#include "editor/model/session/file_defaults.h"

#include <cstdlib>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "base/assets.h"
#include "editor/model/session/config_paths.h"
#include "editor/model/session/material_library_folder.h"
#include "support/scratch_folder.h"

namespace gloss {
namespace {

// Sets an environment variable for the test's lifetime.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : m_name(name) {
    const char* old = std::getenv(name);
    m_had = old != nullptr;
    if (m_had) m_old = old;
    ::setenv(name, value.c_str(), 1);
  }
  ~ScopedEnv() {
    if (m_had) {
      ::setenv(m_name, m_old.c_str(), 1);
    } else {
      ::unsetenv(m_name);
    }
  }

 private:
  const char* m_name;
  bool m_had = false;
  std::string m_old;
};

TEST(FileDefaults, ShippedFilesAreTheAssetsFolders) {
  EXPECT_TRUE(is_shipped_path(asset_path("scenes/spheres.json")));
  EXPECT_TRUE(is_shipped_path(asset_dir()));
  EXPECT_TRUE(is_shipped_path(asset_dir() + "/scenes/../scenes/new.json"));
  ScratchFolder folder;
  EXPECT_FALSE(is_shipped_path(folder.file("scene.json")));
  EXPECT_FALSE(is_shipped_path(""));
}

// "Save and quit" and "Save, then open" rewrote a shipped scene (new-user review): only a scene
// with a file of its own saves in place; every save asks shipped_scene_refusal.
TEST(FileDefaults, OnlyAScenesOwnFileIsSavedInPlace) {
  ScratchFolder folder;
  EXPECT_TRUE(saves_in_place(folder.file("scene.json")));
  EXPECT_FALSE(saves_in_place(asset_path("scenes/spheres.json")));
  EXPECT_FALSE(saves_in_place(""));
  EXPECT_EQ(shipped_scene_refusal(folder.file("scene.json")), "");
  EXPECT_NE(shipped_scene_refusal(asset_path("scenes/spheres.json")).find("a scene gloss ships"),
            std::string::npos);
}

TEST(FileDefaults, ASaveStartsInTheUsersFolderNeverInTheAssets) {
  ScratchFolder home;
  std::filesystem::create_directories(home.path() / "Papers");
  std::filesystem::create_directories(home.path() / "config");
  std::ofstream(home.file("config/user-dirs.dirs"))
      << "# written by xdg-user-dirs-update\nXDG_DESKTOP_DIR=\"$HOME/Desktop\"\n"
         "XDG_DOCUMENTS_DIR=\"$HOME/Papers\"\n";
  ScopedEnv h("HOME", home.path().string());
  ScopedEnv c("XDG_CONFIG_HOME", home.file("config"));
  EXPECT_EQ(documents_dir(), home.path() / "Papers");
  // The last folder the user chose wins; a shipped one or none gives the documents folder.
  EXPECT_EQ(save_folder(home.path()), home.path());
  EXPECT_EQ(save_folder(asset_dir() + "/scenes"), home.path() / "Papers");
  EXPECT_EQ(save_folder(""), home.path() / "Papers");
  EXPECT_EQ(save_folder(home.file("gone")), home.path() / "Papers");
  // Opening may start in the shipped scenes' folder, after the user's own.
  EXPECT_EQ(open_folder("", asset_path("scenes/spheres.json")), asset_dir() + "/scenes");
  EXPECT_EQ(open_folder(home.path(), asset_path("scenes/spheres.json")), home.path());
}

TEST(FileDefaults, WithoutUserDirsTheDocumentsFolderIsHomesDocuments) {
  ScratchFolder home;
  ScopedEnv h("HOME", home.path().string());
  ScopedEnv c("XDG_CONFIG_HOME", home.file("no-config"));
  EXPECT_EQ(documents_dir(), home.path());  // no Documents folder: home itself
  std::filesystem::create_directories(home.path() / "Documents");
  EXPECT_EQ(documents_dir(), home.path() / "Documents");
}

TEST(FileDefaults, NamesComeFromTheSceneOrTheMaterial) {
  EXPECT_EQ(scene_file_name("/x/assets/scenes/spheres.json"), "spheres.json");
  EXPECT_EQ(scene_file_name(""), "untitled.json");
  EXPECT_EQ(file_name_for("polished brass", ".json"), "polished brass.json");
  EXPECT_EQ(file_name_for("cube/red: \"x\"", ".mtl"), "cube-red- -x-.mtl");
  EXPECT_EQ(file_name_for("../..", ".frag"), "untitled.frag");
  EXPECT_EQ(file_name_for("", ".json"), "untitled.json");
}

TEST(FileDefaults, TheLastFolderIsKeptBetweenSessions) {
  ScratchFolder config;
  EXPECT_EQ(load_last_folder(config.path()), std::filesystem::path());
  save_last_folder(config.path(), "/home/someone/scenes");
  EXPECT_EQ(load_last_folder(config.path()), std::filesystem::path("/home/someone/scenes"));
}

TEST(MaterialLibraryFolder, LivesInTheXdgDataFolderAndRoundTrips) {
  ScratchFolder data;
  ScopedEnv d("XDG_DATA_HOME", data.path().string());
  const std::filesystem::path folder = library_folder();
  EXPECT_EQ(folder, data.path() / "gloss" / "materials");
  EXPECT_TRUE(std::filesystem::is_directory(folder));
  Material brass;
  brass.diffuse = {0.78f, 0.57f, 0.11f};
  brass.shininess = 27.9f;
  EXPECT_EQ(save_to_library(folder, "polished brass", brass),
            (folder / "polished brass.json").string());
  std::ofstream(folder / "broken.json") << "{ not json";
  std::ofstream(folder / "old.mtl") << "newmtl chalk\nKd 0.9 0.9 0.9\n";
  std::vector<std::string> errors;
  const std::vector<LibraryMaterial> library = read_library(folder, &errors);
  ASSERT_EQ(library.size(), 2u);
  EXPECT_EQ(library[0].name, "chalk");  // files in name order: old.mtl, polished brass.json
  EXPECT_EQ(library[1].name, "polished brass");
  EXPECT_EQ(library[1].material.diffuse, brass.diffuse);
  EXPECT_EQ(library[1].material.shininess, brass.shininess);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].find("broken.json"), std::string::npos);
}

}  // namespace
}  // namespace gloss
