// Every model of Debian's assimp-testmodels (OBJ, PLY, STL, glTF 2.0) through gloss-cli render,
// as a user would: each renders (exit 0) or fails cleanly (exit 2, one message naming the file);
// never exit 1, never a crash. Skipped when the package is not installed. With GLOSS_CORPUS_OUT
// set to a folder, the PNGs and a table of results (corpus-table.md) are written there.
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "base/error.h"
#include "io/model/model_loader.h"
#include "support/scratch_folder.h"

namespace gloss {
namespace {

const char* const kCorpus = "/usr/share/assimp/models";

std::vector<std::string> corpus_files() {
  namespace fs = std::filesystem;
  std::vector<std::string> files;
  for (const char* folder : {"OBJ", "PLY", "STL", "glTF2"}) {
    const fs::path root = fs::path(kCorpus) / folder;
    std::error_code error;
    if (!fs::is_directory(root, error)) continue;
    for (fs::recursive_directory_iterator it(root, error), end; it != end; it.increment(error)) {
      if (!it->is_regular_file()) continue;
      const std::string path = it->path().string();
      // glTF2 holds .bin buffers and textures too; only the model files are inputs. OBJ, PLY
      // and STL are flat folders with textures and MTL files beside the models.
      if (is_model_file(path) && (std::string(folder) == "glTF2" || it.depth() == 0)) {
        files.push_back(path);
      }
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string vec(const glm::vec3& v) {
  std::ostringstream out;
  out.precision(9);
  out << "[" << v.x << ", " << v.y << ", " << v.z << "]";
  return out.str();
}

// A scene that frames the model from its bounds (when it loads here), lit from the camera's side
// and from above; without bounds the default camera, as the render is expected to fail anyway.
std::string scene_for(const std::string& model) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  try {
    for (const ModelPart& part : load_model(model).parts) {
      glm::vec3 a, b;
      if (!mesh_bounds(part.mesh, a, b)) continue;
      lo = glm::min(lo, a);
      hi = glm::max(hi, b);
    }
  } catch (const InputError&) {
  }
  std::string camera, lights;
  if (lo.x <= hi.x) {
    const glm::vec3 centre = 0.5f * (lo + hi);
    const float radius = std::max(0.5f * glm::length(hi - lo), 1e-6f);
    const glm::vec3 view = glm::normalize(glm::vec3(0.6f, 0.45f, 1.0f));
    const float distance = radius / std::sin(glm::radians(20.0f)) * 1.05f;
    camera = "{\"eye\": " + vec(centre + view * distance) + ", \"target\": " + vec(centre) +
             ", \"fov_y\": 40}";
    lights = "[{\"position\": " + vec(centre + view * distance * 1.5f) +
             ", \"diffuse\": [0.7, 0.7, 0.7], \"specular\": [0.5, 0.5, 0.5]}, {\"position\": " +
             vec(centre + glm::vec3(-0.5f, 2.0f, 0.8f) * distance) +
             ", \"diffuse\": [0.5, 0.5, 0.45], \"specular\": [0.3, 0.3, 0.3]}]";
  } else {
    camera = "{}";
    lights = "[{\"position\": [2, 3, 4]}]";
  }
  return "{\"camera\": " + camera + ", \"background\": [0.12, 0.12, 0.16], \"lights\": " + lights +
         ", \"objects\": [{\"type\": \"mesh\", \"file\": " + json_string(model) +
         "}], \"render\": {\"width\": 96, \"height\": 72, \"spp\": 1}}";
}

struct Outcome {
  int status = -1;  // exit status; -1 when killed by a signal
  std::string err;
};

Outcome render(const std::string& scene, const std::string& png, const ScratchFolder& logs) {
  const std::string err = logs.file("stderr.txt");
  const std::string command = "'" + std::string(GLOSS_CLI_PATH) + "' render '" + scene + "' -o '" +
                              png + "' >/dev/null 2>'" + err + "'";
  const int raw = std::system(command.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, read_all(err)};
}

TEST(ModelCorpus, EveryFileRendersOrFailsWithExitTwoNamingIt) {
  const std::vector<std::string> files = corpus_files();
  if (files.empty()) GTEST_SKIP() << kCorpus << " not installed (Debian package assimp-testmodels)";
  const ScratchFolder work;
  const char* keep = std::getenv("GLOSS_CORPUS_OUT");
  const std::filesystem::path out_dir = keep != nullptr ? keep : work.path().string();
  std::filesystem::create_directories(out_dir / "corpus-png");
  std::ofstream table;
  if (keep != nullptr) {
    table.open(out_dir / "corpus-table.md");
    table << "| file | result | looked at |\n|---|---|---|\n";
  }
  int rendered = 0, refused = 0;
  for (std::size_t i = 0; i < files.size(); ++i) {
    const std::string& file = files[i];
    const std::string relative = std::filesystem::relative(file, kCorpus).string();
    std::string flat = relative;
    std::replace(flat.begin(), flat.end(), '/', '_');
    const std::string scene = work.file("scene" + std::to_string(i) + ".json");
    std::ofstream(scene, std::ios::binary) << scene_for(file);
    const std::string png = (out_dir / "corpus-png" / (flat + ".png")).string();
    const Outcome outcome = render(scene, png, work);
    const std::string message = outcome.err.substr(0, outcome.err.find('\n'));
    // The table names the model, not this test's temporary scene.
    const std::size_t at = message.find(file);
    const std::string shown = at == std::string::npos ? message : message.substr(at);
    if (outcome.status == 0) {
      ++rendered;
      EXPECT_TRUE(std::filesystem::exists(png)) << file;
    } else {
      ++refused;
      EXPECT_EQ(outcome.status, 2) << file << ": " << outcome.err;
      EXPECT_NE(message.find(file), std::string::npos) << file << ": " << outcome.err;
      EXPECT_EQ(std::count(outcome.err.begin(), outcome.err.end(), '\n'), 1) << outcome.err;
    }
    if (table.is_open()) {
      table << "| " << relative << " | "
            << (outcome.status == 0
                    ? std::string("rendered")
                    : "exit " + std::to_string(outcome.status) + ": `" + shown + "`")
            << " | |\n";
    }
  }
  if (table.is_open()) {
    table << "\n"
          << files.size() << " files: " << rendered << " rendered, " << refused << " refused\n";
  }
  std::cout << files.size() << " files: " << rendered << " rendered, " << refused << " refused\n";
}

}  // namespace
}  // namespace gloss
