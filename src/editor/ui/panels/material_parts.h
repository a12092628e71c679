#pragma once
// Parts of the Material panel (material_panel.cpp) kept in a file of their own
// (material_list_panel.cpp): materials with an identity (issue 24, item 2). Each change is a
// command; saving goes through the app's file actions.
#include <string>

namespace gloss {

class Commands;
class FileActions;
struct FileBrowser;
struct MaterialLibrary;
struct MaterialPanelState;
struct Selection;

// The selected object's material by name: rename it, make a copy for the selected objects to
// edit apart, save it to a file or to the user's library.
void draw_material_identity(Commands& commands, const Selection& selection,
                            MaterialPanelState& state, FileActions& files, FileBrowser& browser);

// The scene's materials, each with its rendered ball and how many objects use it: a click gives
// the selected objects that material (reuse), a double-click renames it, a right-click offers the
// rest.
void draw_material_list(Commands& commands, Selection& selection, MaterialPanelState& state,
                        MaterialLibrary& library);

// The user's library (its folder's materials) as swatches, beside the presets: a click loads the
// constants into the selected object's material, as a preset does; a right-click adds one as a
// new material instead.
void draw_user_library(Commands& commands, const Selection& selection, MaterialLibrary& library,
                       FileActions& files);

}  // namespace gloss
