#pragma once
// An OpenGL 3.3 core context without any window system: EGL on Mesa's surfaceless platform
// (third_party/README.md, EGL), for testing the editor's GL pieces without X. Rendering goes
// to FBOs.
#include <string>

namespace gloss::test {

class EglContext {
 public:
  EglContext();  // check ok() / error()
  ~EglContext();
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  bool ok() const { return m_ok; }
  const std::string& error() const { return m_error; }

 private:
  void* m_display = nullptr;
  void* m_context = nullptr;
  bool m_ok = false;
  std::string m_error;
};

}  // namespace gloss::test
