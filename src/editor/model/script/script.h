#pragma once
// Scripted mode: `gloss SCENE.json --script FILE` replays a text file of commands, one per line,
// through the command layer. '#' starts a comment; blank lines are skipped. The line grammar is in
// docs/editor.md. Document lines become Commands; the rest (wait, screenshot, view, quit ...) are
// actions the editor's frame loop or the headless runner carry out.
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "editor/model/document/command.h"
#include "editor/model/view/view_settings.h"
#include "physical/lobe_metrics.h"

namespace gloss {

struct UndoAction {};
struct RedoAction {};
struct WaitAction {
  double timeout_s = 300.0;  // a render that has not converged by then is an error
};
struct ScreenshotAction {
  std::string path;  // a folder (existing, or ending in '/') gets a timestamped name inside it
  ScreenshotKind kind = ScreenshotKind::viewport;
};
struct ViewAction {
  ViewMode mode = ViewMode::render;
  TermView term = TermView::total;  // for ViewMode::single
  // for ViewMode::ab: `view ab`, `view ab snapshot`, `view ab cpu-gl`, `view ab pixel-vertex`,
  // `view ab reference`
  AbSource ab_source = AbSource::models;
  float lobe_elevation_deg = -1.0f;  // for ViewMode::lobe: 0..90, or -1 to keep the current one
  int lobe_log_radius = -1;          // for ViewMode::lobe: 1 `log`, 0 `linear`, -1 keep
};
// ---- Exposure and snapshot comparison (issue 13, items 3 and 4) ----
// `view clipped on|off`: the clipped-pixel overlay.
struct ClippedOverlayAction {
  bool on = false;
};
// `view uv_checker on|off`: the UV checker view (ViewSettings::uv_checker).
struct UvCheckerAction {
  bool on = false;
};
// `snapshot`: keeps the current document as the A side of `view ab snapshot`.
struct SnapshotAction {};
// `select OBJECT`: an index, or a name resolved when the line runs (as ObjectRef below).
struct SelectAction {
  int object = 0;
  std::string name;  // when not empty: the object called so
};
// Prints the editor's frame and latency measurements on stdout, then restarts the frame-time
// window so consecutive `stats` lines measure the interval between them.
struct StatsAction {};
// Lets frames run for a while (measurements, animations).
struct SleepAction {
  double seconds = 1.0;
};
// Starts or stops the orbit-light animation.
struct AnimateAction {
  bool on = false;
};
struct QuitAction {};
// Prints the process's resident memory and what the editor can account for of it (history,
// frames, textures; docs/editor.md, "Memory").
struct MemoryAction {};
// The Quality panel's measurement (quality_measurement.h) at its quick settings: measure starts it
// on the current scene and holds the script until it ends; start does not hold; cancel stops it;
// csv writes the rows so far as tradeoff CSV to path, atomically. raster (`quality raster PATH
// [WIDTH HEIGHT [REFERENCE_SPP]]`, issue 12) measures the raster path's rows
// (editor/gl/raster/raster_tradeoff.h) on the editor's GL thread and writes their CSV to path; the
// size and reference default to the panel's quick settings. It needs the window's GL context.
struct QualityAction {
  enum class Verb { measure, start, cancel, csv, raster };
  Verb verb = Verb::measure;
  std::string path;           // csv and raster
  int width = 0, height = 0;  // raster: image size, pixels; 0: the quick settings'
  int reference_spp = 0;      // raster: the reference's samples per pixel; 0: the quick settings'
};

// Prints what the contract computed at the centre of pixel (x, y) of the document's render size
// (editor/model/measure/pixel_report.h) and pins the editor's pixel inspector there.
struct InspectAction {
  int x = 0, y = 0;
};

// ---- The GLSL path (issue 12) ----
// `export glsl PATH [OBJECT]`: writes the fragment shader of editor/model/export/glsl_export.h for
// the material of object OBJECT (default: the selected object), atomically.
struct ExportGlslAction {
  std::string path;
  int object = -1;  // -1: the host's selected object
};

// `export gltf PATH` (issue 26): the scene as glTF 2.0 (.gltf or .glb, export/gltf_export.h),
// each material's conversion error printed and shown as a notice.
struct ExportGltfAction {
  std::string path;
};

// ---- The physical reference (issue 23) ----
// `reference METAL ROUGHNESS`, `reference dielectric R G B ROUGHNESS`, `reference none`: gives
// the selected object's material a physical reference (or removes it), one undo step.
struct ReferenceAction {
  std::optional<PhysicalReference> reference;
};
// `fit phong|blinn-phong [l2|lightness]`: the selected object's material fitted to its reference
// (editor/model/document/reference_fit.h), one undo step; prints the constants and residuals.
struct FitAction {
  ShadingModel model = ShadingModel::phong;
  LobeMetric metric = LobeMetric::l2;
};

// `renderer cpu|gl|auto`: which renderer draws the viewport (raster_settings.h).
struct RendererAction {
  RendererChoice choice = RendererChoice::cpu;
};
// `shading pixel|vertex`: the raster path's shading frequency.
struct ShadingAction {
  ShadingFrequency frequency = ShadingFrequency::pixel;
};
// `shadow-map SIZE`: texels per cube face side, kMinShadowMapSize..kMaxShadowMapSize.
struct ShadowMapAction {
  int size = 1024;
};
// `shadow-bias TEXELS`: the raster shadow test's bias, >= 0.
struct ShadowBiasAction {
  float texels = 1.5f;
};

// `mouse press X Y [left|right|middle]`, `mouse move X Y`, `mouse release`: the viewport gestures a
// user makes with the mouse, for scripts and end-to-end tests (Automatic's drags). X and Y are
// fractions 0..1 of the viewport's image (its first pane), x to the right, y down. press holds the
// button down at (X, Y); move takes the cursor there with the button still held; release lets go.
// Each line takes effect at the next frame. Without a display the lines do nothing.
struct MouseAction {
  enum class Verb { press, move, release };
  Verb verb = Verb::press;
  float x = 0.5f, y = 0.5f;
  int button = 0;  // 0 left (orbit), 1 right, 2 middle
};

// ---- Objects and material identities (issue 24) ----
// An object as a line names it: an index (a bare whole number) or a name (any other word, or any
// quoted one: `object "12" hide` names the object called 12). Resolved when the line runs, so
// an index after a delete names the object that moved down to it.
struct ObjectRef {
  int index = -1;    // >= 0: by index
  std::string name;  // index < 0: by name
};
// `object add sphere|quad|box|teapot`, `object add model PATH`, `object OBJECT move X Y Z`
// (the translate), `rotate X Y Z` (degrees), `scale S` or `scale SX SY SZ`, `pivot X Y Z`,
// `object OBJECT delete|duplicate|hide|show|solo`, `object OBJECT name TEXT`,
// `material rename OLD NEW`, `assign OBJECT MATERIAL`.
struct ObjectLineAction {
  enum class Verb {
    add,
    add_model,
    field,
    remove,
    duplicate,
    hide,
    show,
    solo,
    name,
    rename_material,
    assign,
    preset  // `preset OBJECT NAME` with OBJECT a name
  };
  Verb verb = Verb::add;
  ObjectRef object;
  ObjectType type = ObjectType::sphere;  // add
  std::string text;   // add_model: the path; name: the new name; rename_material: OLD;
                      // assign: the material's name; preset: the preset's name
  std::string text2;  // rename_material: NEW
  SetField field;     // field: a transform or material field and its value (the index is set
                      // when the line runs)
};

// `save PATH`: the scene saved to PATH as File > Save scene as does (PATH becomes its file).
struct SaveAction {
  std::string path;
};
// `browse save-scene|save-material|save-materials|export-glsl|open-scene|add-model`: the file
// panel opened as the File menu opens it; prints `browse: FOLDER | NAME` (where it starts and
// the name it suggests), so a script can check and a window screenshot can show them.
struct BrowseAction {
  std::string what;
};
// `gizmo move|rotate|scale`: the viewport gizmo's mode (keys W, E, R).
struct GizmoAction {
  GizmoMode mode = GizmoMode::move;
};

// ---- The window's layout (issue 24) ----
// `layout` prints where the panels, the viewport's panes, the legend and the light markers are
// (the editor's layout of its newest frame); `layout maximise on|off`, `layout collapse
// left|right`, `layout expand left|right` and `layout reset` change it as the Panels menu does.
// Without a display they print that there is none.
struct LayoutAction {
  enum class Verb { print, maximise, collapse, expand, reset };
  Verb verb = Verb::print;
  bool on = false;     // maximise on
  bool right = false;  // collapse, expand: the right column (Lights & Scene, View & Quality)
};
// `key KEYS`: the keyboard shortcut the help window (F1) lists as KEYS (`key F1`, `key I`,
// `key Ctrl+Space`, `key [`), as if pressed. An error when no shortcut is called that.
struct KeyAction {
  std::string keys;
};

// ---- The lobe view's plots (issue 24, item 7) ----
// `lobe plot plane|3d|albedo`, `lobe overlay none|snapshot`, `lobe overlay material NAME`,
// `lobe overlay preset NAME`, `lobe turn AZIMUTH_DEG TILT_DEG` (the 3D plot's camera).
struct LobeAction {
  enum class Verb { plot, overlay, turn };
  Verb verb = Verb::plot;
  LobePlot plot = LobePlot::plane;
  LobeOverlay overlay = LobeOverlay::none;
  std::string name;  // overlay material or preset
  float azimuth_deg = 0.0f, tilt_deg = 0.0f;
};

using ScriptAction =
    std::variant<Command, UndoAction, RedoAction, WaitAction, ScreenshotAction, ViewAction,
                 SelectAction, StatsAction, SleepAction, AnimateAction, QuitAction, QualityAction,
                 InspectAction, ClippedOverlayAction, UvCheckerAction, SnapshotAction, MemoryAction,
                 ExportGlslAction, RendererAction, ShadingAction, ShadowMapAction, ShadowBiasAction,
                 MouseAction, ReferenceAction, FitAction, LayoutAction, KeyAction, LobeAction,
                 ObjectLineAction, SaveAction, BrowseAction, GizmoAction, ExportGltfAction>;

struct ScriptLine {
  int line = 0;  // 1-based line number in the file
  std::string text;
  ScriptAction action;
};

struct Script {
  std::string file;  // for messages
  std::vector<ScriptLine> lines;
};

// The object an ObjectRef names in scene now; throws CommandError naming the reference
// ("no object called 'bal' (did you mean 'ball'?)", "no object 7 (the scene has 3)").
int resolve_object(const Scene& scene, const ObjectRef& ref);
// The command an object line makes on scene as it is now. add_model loads the model file
// (InputError naming it; its warnings go to warnings).
Command object_line_command(const Scene& scene, const ObjectLineAction& line,
                            std::vector<std::string>* warnings = nullptr);

// Parses every line first, so a typo anywhere fails before anything runs. Throws InputError
// naming the file and the line ("FILE:LINE: MESSAGE").
Script parse_script(const std::string& text, const std::string& file);
Script load_script(const std::string& path);

}  // namespace gloss
