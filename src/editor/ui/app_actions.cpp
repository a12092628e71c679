// File and export actions of the editor: opening and saving scenes and materials, adding OBJ
// models, screenshots. Errors propagate as InputError / RuntimeFailure for the UI to show.
#include <algorithm>
#include <ctime>
#include <limits>

#include <imgui.h>
#include <glm/gtc/matrix_transform.hpp>

#include "base/error.h"
#include "editor/model/document/document.h"
#include "editor/model/export/export_image.h"
#include "editor/model/export/glsl_export.h"
#include "editor/model/export/shown_image.h"
#include "editor/model/script/script_runner.h"
#include "editor/ui/app.h"
#include "io/model/model_loader.h"
#include "io/scene/scene_loader.h"

namespace gloss {

namespace {

bool has_extension(const std::string& path, const char* extension) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == extension;
}

std::string unique_material_name(const Scene& scene, const std::string& wanted) {
  std::string name = wanted.empty() ? std::string("material") : wanted;
  for (int n = 2; find_material(scene, name) >= 0; ++n) name = wanted + "_" + std::to_string(n);
  return name;
}

}  // namespace

void remember_recent(App& app, RecentKind kind, const std::string& path) {
  app.recent.of(kind).add(path);
  try {
    save_recent_files(app.recent.of(kind), app.config_folder / recent_file_name(kind));
  } catch (const std::exception& e) {
    app.notices.error(std::string("cannot save the recent files: ") + e.what(), app.now_s());
  }
}

void open_scene(App& app, const std::string& requested) {
  const std::string path = requested;  // may refer into the recent list, which changes below
  std::vector<std::string> warnings;
  auto scene = std::make_shared<Scene>(load_scene(path, &warnings));
  // Undoing the open gives back the earlier document with its own saved/unsaved state.
  app.commands.open_document(scene, "open " + std::filesystem::path(path).filename().string());
  app.selected_object = 0;
  app.selected_light = 0;
  remember_recent(app, RecentKind::scene, path);
  for (const std::string& w : warnings) app.notices.info("warning: " + w, app.now_s());
  app.notices.info("opened " + path, app.now_s());
}

void request_open_scene(App& app, const std::string& path) {
  // Scripts answer no questions; they replace the document as they say.
  if (app.unsaved.request_open(path, app.commands.dirty() && !app.script)) open_scene(app, path);
}

void add_model(App& app, const std::string& path) {
  const Model model = load_model(path);
  // Fit the model into a 2-unit box centred on the camera target.
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const ModelPart& part : model.parts) {
    glm::vec3 a, b;
    if (!mesh_bounds(part.mesh, a, b)) continue;
    lo = glm::min(lo, a);
    hi = glm::max(hi, b);
  }
  if (!(lo.x <= hi.x)) throw InputError(path, "the model has no vertices");
  const glm::vec3 extent = hi - lo;
  const float size = std::max(extent.x, std::max(extent.y, extent.z));
  const float scale = size > 0.0f ? 2.0f / size : 1.0f;

  auto scene = std::make_shared<Scene>(app.commands.scene());
  const glm::vec3 position = scene->camera.target - (lo + hi) * 0.5f * scale;
  // The scene loader's order: scale, then rotate_y (0 here), then translate.
  const glm::mat4 transform =
      glm::scale(glm::translate(glm::mat4(1.0f), position), glm::vec3(scale));
  const std::string absolute = std::filesystem::absolute(path).lexically_normal().string();
  const std::string stem = std::filesystem::path(path).stem().string();
  for (const ModelPart& part : model.parts) {
    Material material;
    std::string material_name = part.material_name.empty() ? stem : part.material_name;
    for (std::size_t i = 0; i < model.material_names.size(); ++i) {
      if (model.material_names[i] == part.material_name) material = model.materials[i];
    }
    scene->materials.push_back(material);
    scene->material_names.push_back(unique_material_name(*scene, material_name));
    Object object;
    object.name = stem + (part.material_name.empty() ? "" : ":" + part.material_name);
    object.type = ObjectType::mesh;
    object.material = static_cast<int>(scene->materials.size()) - 1;
    object.params.file = absolute;
    object.params.group = part.material_name;
    object.params.position = position;
    object.params.scale = glm::vec3(scale);
    object.params.smooth = true;
    Mesh mesh = part.mesh;
    transform_mesh(mesh, transform);
    object.mesh = std::make_shared<const Mesh>(std::move(mesh));
    scene->objects.push_back(std::move(object));
  }
  const int first_new = static_cast<int>(app.commands.scene().objects.size());
  app.commands.execute(
      ReplaceScene{scene, "add " + std::filesystem::path(path).filename().string()});
  app.commands.seal();
  app.selected_object = first_new;
  remember_recent(app, RecentKind::model, path);
  for (const std::string& w : model.warnings) app.notices.info("warning: " + w, app.now_s());
  app.notices.info("added " + std::to_string(model.parts.size()) + " object(s) from " + path,
                   app.now_s());
}

void save_scene_as(App& app, const std::string& requested) {
  const std::string path = requested;  // may refer into the document, which changes below
  Scene scene = app.commands.scene();
  move_document(scene, path);
  save_scene(scene, path);
  app.commands.set_path(path);
  app.commands.mark_saved();
  remember_recent(app, RecentKind::scene, path);
  app.notices.info("saved scene " + path, app.now_s());
}

void load_materials(App& app, const std::string& path) {
  std::vector<NamedMaterial> materials =
      has_extension(path, ".mtl") ? load_mtl(path) : load_materials_json(path);
  if (materials.empty()) throw InputError(path, "the file holds no materials");
  app.library = std::move(materials);
  app.library_source = std::filesystem::path(path).filename().string();
  remember_recent(app, RecentKind::materials, path);
  app.notices.info("loaded " + std::to_string(app.library.size()) + " material(s) from " + path +
                       "; apply them in the Material panel",
                   app.now_s());
}

void save_materials(App& app, const std::string& path) {
  const Scene& scene = app.commands.scene();
  std::vector<NamedMaterial> materials;
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const std::string name =
        i < scene.material_names.size() ? scene.material_names[i] : "material" + std::to_string(i);
    materials.emplace_back(name, scene.materials[i]);
  }
  if (has_extension(path, ".mtl")) {
    save_mtl(path, materials);
  } else {
    save_materials_json(path, materials);
  }
  app.notices.info("saved " + std::to_string(materials.size()) + " material(s) to " + path,
                   app.now_s());
}

void export_glsl_shader(App& app, const std::string& path) {
  const Scene& scene = app.commands.scene();
  if (app.selected_object < 0 || app.selected_object >= static_cast<int>(scene.objects.size())) {
    throw std::runtime_error("select an object to export its material");
  }
  const int material = scene.objects[static_cast<std::size_t>(app.selected_object)].material;
  write_glsl_export(path, scene, material);
  app.notices.info(
      "exported the GLSL shader of " + object_label(scene, app.selected_object) + " to " + path,
      app.now_s());
}

void start_screenshot(App& app, ScreenshotKind kind, const std::string& path, bool from_script) {
  if (kind == ScreenshotKind::window) {
    app.capture = {true, path, from_script, from_script ? 0 : 1};
    if (!from_script) close_menus();
    return;
  }
  if (kind == ScreenshotKind::shown) {
    // The frame on screen as it is, written on a worker (shown_image.h).
    PendingExport job;
    job.from_script = from_script;
    job.path = std::async(std::launch::async,
                          [frame = app.viewport.shown_images(), scene = app.commands.scene(),
                           view = app.view, raster = app.viewport.shown_raster_a(), path] {
                            if (frame == nullptr) throw std::runtime_error("no frame is shown yet");
                            return write_shown(path.empty() ? view.screenshot_dir + "/" : path,
                                               *frame, scene, view, raster);
                          });
    app.exports.push_back(std::move(job));
    return;
  }
  const Scene scene = app.commands.scene();
  ViewSettings view = app.view;
  // The raster path draws the viewport: the export is its frame at the document's size, drawn
  // here (it needs the GL context) and written on the worker. Automatic exports the still image,
  // the ray tracer's.
  std::shared_ptr<const RenderedFrame> raster;
  std::string raster_error;
  if (view.renderer == RendererChoice::gl) {
    try {
      raster = app.viewport.render_raster(scene, view.raster, export_needs_terms(view, kind));
      if (!raster) raster_error = "the raster path is unavailable (see the notice)";
    } catch (const std::exception& e) {
      raster_error = std::string("the raster path failed: ") + e.what();
    }
  } else {
    view.renderer = RendererChoice::cpu;
  }
  PendingExport job;
  job.from_script = from_script;
  job.path = std::async(std::launch::async, [scene, view, kind, path, raster, raster_error] {
    if (!raster_error.empty()) throw std::runtime_error(raster_error);
    const Image image =
        raster ? export_image(raster->images, view, kind) : render_export(scene, view, kind);
    const TextChunks text = export_text(scene, view, kind);
    if (path.empty()) {
      return write_png_unique(view.screenshot_dir, std::string("gloss-") + to_string(kind), image,
                              scene.render.srgb, text, std::time(nullptr));
    }
    return write_export(path, image, scene.render.srgb, text);
  });
  app.exports.push_back(std::move(job));
  if (!from_script)
    app.notices.info(
        std::string("rendering the ") + to_string(kind) + " screenshot at full resolution ...",
        app.now_s());
}

void poll_exports(App& app) {
  for (auto it = app.exports.begin(); it != app.exports.end();) {
    if (it->path.wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
      ++it;
      continue;
    }
    try {
      const std::filesystem::path written = it->path.get();
      const std::string absolute = std::filesystem::absolute(written).lexically_normal().string();
      app.notices.info("saved screenshot " + absolute, app.now_s());
      if (it->from_script) std::printf("saved %s\n", absolute.c_str());
    } catch (const std::exception& e) {
      app.notices.error(std::string("screenshot failed: ") + e.what(), app.now_s());
      if (it->from_script) {
        app.exit_code = 1;
        app.quit = true;
      }
    }
    std::fflush(stdout);
    it = app.exports.erase(it);
  }
}

void capture_window(App& app) {
  int width = 0, height = 0;
  glfwGetFramebufferSize(app.window, &width, &height);
  std::vector<unsigned char> rgb(static_cast<std::size_t>(width) * height * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
  // GL rows run bottom to top; images top to bottom. 8-bit values map exactly back through the
  // PNG writer's clamp-and-round (v / 255 * 255 rounds to v).
  Image image(width, height);
  for (int y = 0; y < height; ++y) {
    const unsigned char* row = &rgb[static_cast<std::size_t>(height - 1 - y) * width * 3];
    for (int x = 0; x < width; ++x) {
      image.at(x, y) = glm::vec3(row[3 * x], row[3 * x + 1], row[3 * x + 2]) / 255.0f;
    }
  }
  const WindowCapture capture = app.capture;
  app.capture = {};
  const ViewSettings view = app.view;
  const TextChunks text = export_text(app.commands.scene(), view, ScreenshotKind::window);
  PendingExport job;
  job.from_script = capture.from_script;
  job.path = std::async(std::launch::async, [image, text, capture, view] {
    if (capture.path.empty()) {
      return write_png_unique(view.screenshot_dir, "gloss-window", image, false, text,
                              std::time(nullptr));
    }
    return write_export(capture.path, image, false, text);
  });
  app.exports.push_back(std::move(job));
}

void browser_action(App& app, const std::string& path) {
  try {
    switch (app.browser.purpose) {
      case BrowsePurpose::open_scene:
        request_open_scene(app, path);
        break;
      case BrowsePurpose::add_model:
        add_model(app, path);
        break;
      case BrowsePurpose::load_materials:
        load_materials(app, path);
        break;
      case BrowsePurpose::save_scene:
        save_scene_as(app, path);
        break;
      case BrowsePurpose::save_materials:
        save_materials(app, path);
        break;
      case BrowsePurpose::export_glsl:
        export_glsl_shader(app, path);
        break;
    }
    app.browser.open = false;
  } catch (const std::exception& e) {
    // The action failed before touching the document; the panel stays open with the reason.
    app.browser.error = e.what();
    app.browser.confirm_replace.clear();
  }
}

void request_quit(App& app) {
  if (app.commands.dirty() && !app.script) {
    app.confirm_quit = true;
  } else {
    app.quit = true;
  }
}

void undo(App& app) {
  const std::string label = app.commands.undo_label();
  if (app.commands.undo()) app.notices.info("undid " + label, app.now_s());
}

void redo(App& app) {
  const std::string label = app.commands.redo_label();
  if (app.commands.redo()) app.notices.info("redid " + label, app.now_s());
}

}  // namespace gloss

namespace gloss {

void snapshot_and_compare(App& app) {
  app.snapshot = take_snapshot(app.commands, app.snapshot);
  app.view.mode = ViewMode::ab;
  app.view.ab_source = AbSource::snapshot;
  app.notices.info(app.snapshot->label + " taken: A shows it, B the live scene", app.now_s());
}

}  // namespace gloss
