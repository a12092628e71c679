#pragma once
// Every panel and window of the editor, one function each. A function's parameters are all it
// can touch: the parts of the App it reads (const) or changes (view settings, selection, its own
// state), and for the document the door it writes through, Commands (parts/commands.h: panels
// never change the document otherwise). An app-level action comes as its own part: FileBrowser
// (the file panel), Exports (screenshots), FileActions (open, save, quit). layout.cpp draws them,
// handing each its parts from the App.
#include <optional>

#include <imgui.h>

#include "editor/model/view/ab_compare.h"
#include "editor/model/view/view_settings.h"

namespace gloss {

class CommandLayer;
class Commands;
class Exports;
class FileActions;
class Viewport;
struct FileBrowser;
struct FrameTimes;
struct InspectorState;
struct LayoutState;
struct MaterialLibrary;
struct MaterialPanelState;
struct Notices;
struct OpenWindows;
struct OutlinerState;
struct QualityState;
struct ReferencePanelState;
struct RunState;
struct Selection;
struct Session;

// The main menu bar: File, Edit, Object, View, Panels, Help. Items call the same actions as the
// shortcuts; Panels changes the layout (collapsed panels, the maximised viewport).
void draw_menu_bar(Commands& commands, Selection& selection, ViewSettings& view,
                   std::optional<Snapshot>& snapshot, Session& session, FileActions& files,
                   Exports& exports, OpenWindows& windows, LayoutState& layout);
// The Material panel: the selected object's material (its name, a copy, saving it), its
// constants and maps, the presets and the user's library, the scene's materials, the shading
// model. Loading a map opens the file browser.
void draw_material_panel(Commands& commands, Selection& selection, ViewSettings& view,
                         MaterialPanelState& state, MaterialLibrary& library, FileActions& files,
                         FileBrowser& browser, ImVec2 pos, ImVec2 size);
// The Outliner (outliner_panel.cpp): the scene's objects in a list, adding, duplicating,
// deleting, hiding, solo, renaming, framing; the selected object's name, material and transform.
void draw_outliner(Commands& commands, Selection& selection, OutlinerState& state,
                   FileBrowser& browser, ImVec2 pos, ImVec2 size);
// Turns the camera to the selected objects and fits them in the view (key F, the Outliner's
// Frame): one command.
void frame_selection(Commands& commands, const Selection& selection);
// The Reference panel: the selected object's material against a physical reference, the
// material | reference A/B view, Fit Phong / Fit Blinn-Phong (on a worker, applied in one step).
void draw_reference_panel(Commands& commands, Selection& selection, ViewSettings& view,
                          ReferencePanelState& state, ImVec2 pos, ImVec2 size);
// The Lights & Scene panel: lights, the scene's own fields, opening files.
void draw_lights_panel(Commands& commands, Selection& selection, ViewSettings& view,
                       FileBrowser& browser, ImVec2 pos, ImVec2 size);
// The View & Quality panel: renderer, view mode, render settings, screenshots.
void draw_view_panel(Commands& commands, ViewSettings& view, Viewport& viewport,
                     std::optional<Snapshot>& snapshot, OpenWindows& windows, Exports& exports,
                     ImVec2 pos, ImVec2 size);
// The status bar: renderer, progress, frame times, delays, the newest notice.
void draw_status_bar(const Viewport& viewport, const ViewSettings& view, const FrameTimes& times,
                     const Notices& notices, const Session& session, ImVec2 pos, ImVec2 size);
// The help window (F1, OpenWindows::help).
void draw_help_window(OpenWindows& windows, const Session& session);
// The Quality window (OpenWindows::quality); "Use" emits commands or sets the preview scale.
void draw_quality_panel(QualityState& quality, OpenWindows& windows, ViewSettings& view,
                        Commands& commands, ImVec2 pos, ImVec2 size);
// The pixel inspector window (view.show_inspector), reading the pixel under the viewport's
// cursor or the pinned one.
void draw_inspector(InspectorState& state, ViewSettings& view, const CommandLayer& document,
                    const std::optional<Snapshot>& snapshot, const Viewport& viewport,
                    ImVec2 viewport_pos, ImVec2 viewport_size);
// The session's questions (session_modals.cpp): recover a crashed session's document
// (Session::offered_recovery), quit with unsaved changes (OpenWindows::quit_question), open
// another scene over unsaved changes (Session::unsaved).
void draw_recovery_modal(const Session& session, FileActions& files);
void draw_quit_modal(OpenWindows& windows, Commands& commands, FileActions& files, RunState& run);
void draw_open_modal(Session& session, Commands& commands, FileActions& files);

// Keeps the current document as the snapshot and shows the snapshot | live A/B view (the View
// menu, the View panel's button, Ctrl+B).
void snapshot_and_compare(Commands& commands, std::optional<Snapshot>& snapshot,
                          ViewSettings& view);

}  // namespace gloss
