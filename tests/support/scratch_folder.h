#pragma once
// A fresh, empty folder per test under the system temp folder, removed with its contents when the
// test ends, so tests never see each other's files.
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include <gtest/gtest.h>

namespace gloss {

class ScratchFolder {
 public:
  ScratchFolder() {
    static int counter = 0;
    const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string test_name =
        test != nullptr ? std::string(test->test_suite_name()) + "." + test->name() : "none";
    m_path =
        std::filesystem::temp_directory_path() / ("gloss-test-" + std::to_string(::getpid()) + "-" +
                                                  std::to_string(counter++) + "-" + test_name);
    std::filesystem::remove_all(m_path);
    std::filesystem::create_directories(m_path);
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(m_path, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;

  const std::filesystem::path& path() const { return m_path; }
  // The path of name inside the folder (the file need not exist).
  std::string file(const std::string& name) const { return (m_path / name).string(); }
  // The names of everything in the folder, sorted.
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(m_path)) {
      names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
  }

 private:
  std::filesystem::path m_path;
};

}  // namespace gloss
