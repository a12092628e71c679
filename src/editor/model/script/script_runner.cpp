#include "editor/model/script/script_runner.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "base/error.h"
#include "base/overloaded.h"
#include "editor/model/document/document.h"
#include "editor/model/document/reference_fit.h"
#include "editor/model/export/glsl_export.h"
#include "editor/model/export/gltf_file.h"
#include "editor/model/measure/memory_report.h"
#include "editor/model/measure/pixel_report.h"
#include "editor/model/session/file_defaults.h"
#include "io/scene/scene_loader.h"
#include "reference/pixel_inspection.h"

namespace gloss {

namespace {

LineResult bad_line(const std::string& where, const std::string& message) {
  std::fprintf(stderr, "error: %s%s\n", where.c_str(), message.c_str());
  return LineResult::stop(2);
}

// `inspect X Y`: the same for both hosts, a reading of the document (the reference path) printed
// on stdout; the editor's inspector is pinned there.
LineResult inspect(ScriptHost& host, const InspectAction& a, const std::string& where) {
  const Scene& scene = host.layer().scene();
  if (a.x >= scene.render.width || a.y >= scene.render.height) {
    return bad_line(where, "pixel " + std::to_string(a.x) + " " + std::to_string(a.y) +
                               " is outside the " + std::to_string(scene.render.width) + "x" +
                               std::to_string(scene.render.height) + " render");
  }
  std::fputs(pixel_report(inspect_pixel(scene, a.x, a.y)).c_str(), stdout);
  std::fflush(stdout);
  ViewSettings& view = host.view();
  view.show_inspector = true;
  view.inspect_pinned = true;
  view.inspect_x = a.x;
  view.inspect_y = a.y;
  return LineResult::go_on();
}

// `export glsl PATH [OBJECT]` (issue 12): the same for both hosts, text only (no GL needed).
LineResult export_glsl_line(ScriptHost& host, const ExportGlslAction& a, const std::string& where) {
  const Scene& scene = host.layer().scene();
  const int object = a.object >= 0 ? a.object : host.selected_object();
  if (object < 0 || object >= static_cast<int>(scene.objects.size())) {
    return bad_line(where, "no object " + std::to_string(object));
  }
  const int material = scene.objects[static_cast<std::size_t>(object)].material;
  try {
    write_glsl_export(a.path, scene, material);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s%s\n", where.c_str(), e.what());
    return LineResult::stop(1);
  }
  // Named as the panels name them: the material's name, the object's label.
  const std::string material_name =
      material >= 0 && material < static_cast<int>(scene.material_names.size())
          ? scene.material_names[static_cast<std::size_t>(material)]
          : std::to_string(material);
  std::printf("export glsl: %s (material '%s' of %s)\n", a.path.c_str(), material_name.c_str(),
              object_label(scene, object).c_str());
  std::fflush(stdout);
  return LineResult::go_on();
}

// `export gltf PATH` (issue 26): the same for both hosts; the conversions' errors printed, the
// summary as a notice.
LineResult export_gltf_line(ScriptHost& host, const ExportGltfAction& a, const std::string& where) {
  std::string summary;
  try {
    summary = write_gltf_file(host.layer().scene(), a.path, true);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s%s\n", where.c_str(), e.what());
    return LineResult::stop(1);
  }
  std::printf("export gltf: %s\n", summary.c_str());
  std::fflush(stdout);
  host.notify(summary);
  return LineResult::go_on();
}

// `reference ...` and `fit ...` (issue 23): commands on the selected object, the fit's report
// printed on stdout.
LineResult reference_line(ScriptHost& host, const ReferenceAction& a) {
  host.layer().execute(SetReference{host.selected_object(), a.reference});
  host.layer().seal();
  return LineResult::go_on();
}

LineResult fit_line(ScriptHost& host, const FitAction& a) {
  const ReferenceFit fit =
      fit_to_reference(host.layer().scene(), host.selected_object(), a.model, a.metric);
  host.layer().execute(fit.command);
  host.layer().seal();
  for (const std::string& line : fit_report_lines(fit.report))
    std::printf("fit: %s\n", line.c_str());
  std::fflush(stdout);
  return LineResult::go_on();
}

// The object and material lines (issue 24): resolved against the document as it is now, then
// one command; what was added is selected and named on stdout.
LineResult object_line(ScriptHost& host, const ObjectLineAction& a, const std::string& where) {
  std::vector<std::string> warnings;
  const std::size_t before = host.layer().scene().objects.size();
  Command command;
  try {
    command = object_line_command(host.layer().scene(), a, &warnings);
  } catch (const InputError& e) {
    return bad_line(where, e.what());
  }
  for (const std::string& w : warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  host.layer().execute(command);
  host.layer().seal();
  const Scene& scene = host.layer().scene();
  if (a.verb == ObjectLineAction::Verb::add || a.verb == ObjectLineAction::Verb::add_model) {
    std::vector<int> added;
    std::string names;
    for (std::size_t i = before; i < scene.objects.size(); ++i) {
      added.push_back(static_cast<int>(i));
      names += (names.empty() ? "" : ", ") + std::to_string(i) + " '" + scene.objects[i].name + "'";
    }
    host.select_objects(added);
    std::printf("added %s\n", names.c_str());
    std::fflush(stdout);
  }
  return LineResult::go_on();
}

}  // namespace

Snapshot take_snapshot(const CommandLayer& layer, const std::optional<Snapshot>& previous) {
  int number = 1;
  if (previous && previous->label.rfind("snapshot ", 0) == 0) {
    number = std::atoi(previous->label.c_str() + 9) + 1;
  }
  return Snapshot{layer.scene(), layer.revision(), "snapshot " + std::to_string(number)};
}

LineResult run_script_line(const Script& script, const ScriptLine& line, ScriptHost& host) {
  const std::string where = script.file + ":" + std::to_string(line.line) + ": ";
  try {
    return std::visit(
        Overloaded{
            [&](const Command& command) {
              host.layer().execute(command);
              host.layer().seal();
              return LineResult::go_on();
            },
            [&](const UndoAction&) {
              if (!host.layer().undo()) throw CommandError("nothing to undo");
              return LineResult::go_on();
            },
            [&](const RedoAction&) {
              if (!host.layer().redo()) throw CommandError("nothing to redo");
              return LineResult::go_on();
            },
            [&](const ViewAction& a) {
              if (a.mode == ViewMode::ab && a.ab_source == AbSource::snapshot && !host.snapshot()) {
                return bad_line(where,
                                "no snapshot to compare with: take one "
                                "with 'snapshot' first");
              }
              if (a.mode == ViewMode::ab) host.view().ab_source = a.ab_source;
              host.view().mode = a.mode;
              if (a.mode == ViewMode::single) host.view().single = a.term;
              if (a.lobe_elevation_deg >= 0.0f) {
                host.view().lobe_elevation_deg = a.lobe_elevation_deg;
              }
              if (a.lobe_log_radius >= 0) host.view().lobe_log_radius = a.lobe_log_radius == 1;
              return LineResult::go_on();
            },
            [&](const SelectAction& a) {
              const Scene& scene = host.layer().scene();
              if (!a.name.empty()) {
                host.select(resolve_object(scene, ObjectRef{-1, a.name}));  // throws when absent
                return LineResult::go_on();
              }
              if (a.object >= static_cast<int>(scene.objects.size())) {
                return bad_line(where, "no object " + std::to_string(a.object));
              }
              host.select(a.object);
              return LineResult::go_on();
            },
            [&](const AnimateAction& a) {
              host.view().orbit_light = a.on;
              return LineResult::go_on();
            },
            [&](const QuitAction&) { return LineResult::stop(0); },
            [&](const ClippedOverlayAction& a) {
              host.view().show_clipped = a.on;
              return LineResult::go_on();
            },
            [&](const UvCheckerAction& a) {
              host.view().uv_checker = a.on;
              return LineResult::go_on();
            },
            [&](const SnapshotAction&) {
              host.snapshot() = take_snapshot(host.layer(), host.snapshot());
              std::printf("snapshot: %s\n", host.snapshot()->label.c_str());
              return LineResult::go_on();
            },
            [&](const WaitAction& a) { return host.wait(a, where); },
            [&](const ScreenshotAction& a) { return host.screenshot(a, where); },
            [&](const StatsAction&) { return host.stats(); },
            [&](const SleepAction& a) { return host.sleep(a); },
            [&](const QualityAction& a) { return host.quality(a, where); },
            [&](const InspectAction& a) { return inspect(host, a, where); },
            [&](const MemoryAction&) { return host.memory(); },
            [&](const MouseAction& a) { return host.mouse(a); },
            [&](const LayoutAction& a) { return host.layout(a, where); },
            [&](const LobeAction& a) {
              ViewSettings& view = host.view();
              switch (a.verb) {
                case LobeAction::Verb::plot:
                  view.lobe_plot = a.plot;
                  break;
                case LobeAction::Verb::overlay:
                  if (a.overlay == LobeOverlay::material) {
                    const std::vector<std::string>& names = host.layer().scene().material_names;
                    if (std::find(names.begin(), names.end(), a.name) == names.end()) {
                      return bad_line(where, "no material '" + a.name + "'");
                    }
                  }
                  if (a.overlay == LobeOverlay::snapshot && !host.snapshot()) {
                    return bad_line(where,
                                    "no snapshot to compare with: take one with "
                                    "'snapshot' first");
                  }
                  view.lobe_overlay = a.overlay;
                  view.lobe_overlay_name = a.name;
                  break;
                case LobeAction::Verb::turn:
                  view.lobe_azimuth_deg = a.azimuth_deg;
                  view.lobe_tilt_deg = a.tilt_deg;
                  break;
              }
              return LineResult::go_on();
            },
            [&](const KeyAction& a) { return host.key(a, where); },
            [&](const ExportGlslAction& a) { return export_glsl_line(host, a, where); },
            [&](const ExportGltfAction& a) { return export_gltf_line(host, a, where); },
            [&](const ReferenceAction& a) { return reference_line(host, a); },
            [&](const FitAction& a) { return fit_line(host, a); },
            [&](const RendererAction& a) {
              host.view().renderer = a.choice;
              return LineResult::go_on();
            },
            [&](const ShadingAction& a) {
              host.view().raster.shading = a.frequency;
              return LineResult::go_on();
            },
            [&](const ShadowMapAction& a) {
              host.view().raster.shadow_map_size = a.size;
              return LineResult::go_on();
            },
            [&](const ObjectLineAction& a) { return object_line(host, a, where); },
            [&](const SaveAction& a) {
              // Every host: never over a scene gloss ships (bad input, exit 2).
              if (const std::string refusal = shipped_scene_refusal(a.path); !refusal.empty()) {
                return bad_line(where, refusal);
              }
              return host.save(a, where);
            },
            [&](const BrowseAction& a) { return host.browse(a); },
            [&](const GizmoAction& a) {
              host.view().gizmo = a.mode;
              return LineResult::go_on();
            },
            [&](const ShadowBiasAction& a) {
              host.view().raster.shadow_bias = a.texels;
              return LineResult::go_on();
            },
        },
        line.action);
  } catch (const CommandError& e) {
    return bad_line(where, e.what());
  }
}

LineResult ScriptHost::save(const SaveAction& a, const std::string& where) {
  try {
    save_scene(layer().scene(), a.path);  // relative file names follow the new folder
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s%s\n", where.c_str(), e.what());
    return LineResult::stop(1);
  }
  layer().set_path(a.path);
  layer().mark_saved();
  std::printf("saved scene %s\n", a.path.c_str());
  std::fflush(stdout);
  return LineResult::go_on();
}

LineResult ScriptHost::browse(const BrowseAction& a) {
  const Scene& scene = layer().scene();
  const bool save = a.what.rfind("save", 0) == 0 || a.what == "export-glsl";
  const std::filesystem::path folder = save ? save_folder("") : open_folder("", scene.path);
  std::printf("browse: %s | %s\n", folder.string().c_str(),
              suggested_file_name(scene, selected_object(), a.what).c_str());
  std::fflush(stdout);
  return LineResult::go_on();
}

LineResult ScriptHost::memory() {
  std::printf("memory: %s\n", memory_text(layer(), ViewMemory{}).c_str());
  std::fflush(stdout);
  return LineResult::go_on();
}

LineResult ScriptHost::layout(const LayoutAction&, const std::string&) {
  std::printf("layout: no display, no window\n");
  std::fflush(stdout);
  return LineResult::go_on();
}

LineResult ScriptHost::key(const KeyAction& action, const std::string&) {
  std::printf("key %s: no display, no window\n", action.keys.c_str());
  std::fflush(stdout);
  return LineResult::go_on();
}

}  // namespace gloss
