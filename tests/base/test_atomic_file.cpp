#include "base/atomic_file.h"

#include <signal.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <gtest/gtest.h>

#include "base/error.h"
#include "support/scratch_folder.h"

namespace gloss {
namespace {

std::string read_back(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(AtomicFile, WritesTheTextAndLeavesNoTemporary) {
  ScratchFolder folder;
  const std::string path = folder.file("out.txt");
  write_text_atomically(path, "hello\n");
  EXPECT_EQ(read_back(path), "hello\n");
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"out.txt"});
}

TEST(AtomicFile, ReplacesAnExistingTarget) {
  ScratchFolder folder;
  const std::string path = folder.file("out.txt");
  write_text_atomically(path, "old contents, longer than the new");
  write_text_atomically(path, "new");
  EXPECT_EQ(read_back(path), "new");
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"out.txt"});
}

TEST(AtomicFile, ThrowingWriterLeavesNeitherTargetNorTemporary) {
  ScratchFolder folder;
  const std::string path = folder.file("out.bin");
  std::string seen_temp;
  EXPECT_THROW(write_atomically(path,
                                [&](const std::string& temp_path) {
                                  seen_temp = temp_path;
                                  std::ofstream(temp_path) << "half written";
                                  throw std::runtime_error("writer failed");
                                }),
               std::runtime_error);
  EXPECT_NE(seen_temp, path);
  EXPECT_TRUE(folder.entries().empty());
}

TEST(AtomicFile, TemporaryIsBesideTheTarget) {
  ScratchFolder folder;
  const std::string path = folder.file("out.bin");
  write_atomically(path, [&](const std::string& temp_path) {
    EXPECT_EQ(std::filesystem::path(temp_path).parent_path(), folder.path());
    std::ofstream(temp_path) << "x";
  });
  EXPECT_EQ(read_back(path), "x");
}

TEST(AtomicFile, ExistingTargetIsKeptIntactWhenTheWriteFails) {
  ScratchFolder folder;
  const std::string path = folder.file("keep.txt");
  write_text_atomically(path, "precious");
  EXPECT_THROW(write_atomically(path,
                                [](const std::string& temp_path) {
                                  std::ofstream(temp_path) << "garbage";
                                  throw RuntimeFailure("disk full");
                                }),
               RuntimeFailure);
  EXPECT_EQ(read_back(path), "precious");
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"keep.txt"});
}

TEST(AtomicFile, ReplacementKeepsTheTargetsPermissions) {
  ScratchFolder folder;
  const std::string path = folder.file("mode.txt");
  write_text_atomically(path, "a");
  ASSERT_EQ(::chmod(path.c_str(), 0640), 0);
  write_text_atomically(path, "b");
  struct stat info {};
  ASSERT_EQ(::stat(path.c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0640u);
}

TEST(AtomicFile, MissingFolderThrowsRuntimeFailureNamingThePath) {
  ScratchFolder folder;
  const std::string path = folder.file("no/such/folder/out.txt");
  bool writer_called = false;
  try {
    write_atomically(path, [&](const std::string&) { writer_called = true; });
    ADD_FAILURE() << "no RuntimeFailure";
  } catch (const RuntimeFailure& error) {
    EXPECT_EQ(std::string(error.what()).rfind("cannot write " + path + ": ", 0), 0u)
        << error.what();
  }
  EXPECT_FALSE(writer_called);
  EXPECT_TRUE(folder.entries().empty());
}

TEST(AtomicFile, TargetThatIsAFolderFailsAndLeavesNoTemporary) {
  ScratchFolder folder;
  std::filesystem::create_directory(folder.path() / "taken");
  EXPECT_THROW(write_text_atomically(folder.file("taken"), "x"), RuntimeFailure);
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"taken"});
}

TEST(AtomicFile, ConcurrentWritersToOneTargetLeaveOneWholeVersion) {
  ScratchFolder folder;
  const std::string path = folder.file("shared.txt");
  std::vector<std::string> versions;
  for (char c = 'a'; c < 'e'; ++c) versions.emplace_back(100000, c);
  std::vector<std::thread> threads;
  for (const std::string& version : versions) {
    threads.emplace_back([&path, &version] {
      for (int i = 0; i < 5; ++i) write_text_atomically(path, version);
    });
  }
  for (std::thread& thread : threads) thread.join();
  const std::string final_text = read_back(path);
  EXPECT_NE(std::find(versions.begin(), versions.end(), final_text), versions.end());
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"shared.txt"});
}

TEST(AtomicFile, ReadTextFileReturnsEveryByte) {
  ScratchFolder folder;
  const std::string bytes("a\0b\r\n\xff", 6);
  std::ofstream(folder.file("bytes.bin"), std::ios::binary) << bytes;
  EXPECT_EQ(read_text_file(folder.file("bytes.bin")), bytes);
}

TEST(AtomicFile, ReadTextFileOfMissingFileOrFolderThrowsInputErrorNamingThePath) {
  ScratchFolder folder;
  const std::string missing = folder.file("absent.txt");
  try {
    read_text_file(missing);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), missing);
    EXPECT_NE(error.message().find("cannot read"), std::string::npos) << error.message();
  }
  EXPECT_THROW(read_text_file(folder.path().string()), InputError);
}

// A writer killed mid-write (kill -9 of a render) leaves no temporary behind.
TEST(AtomicFile, KilledWriterLeavesNoTemporary) {
  ScratchFolder folder;
  const std::string path = folder.file("big.png");
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    write_stream_atomically(path, [](std::FILE* file) {
      const std::string chunk(1 << 20, 'x');
      std::fwrite(chunk.data(), 1, chunk.size(), file);
      std::fflush(file);
      ::raise(SIGKILL);
    });
    ::_exit(0);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_TRUE(folder.entries().empty());
}

// Where a named temporary was left (a file system without O_TMPFILE, an outside program's
// writer), the next write of the same target removes it once its process is gone.
TEST(AtomicFile, StaleTemporaryOfADeadProcessIsRemovedByTheNextWrite) {
  ScratchFolder folder;
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) ::_exit(0);
  ASSERT_EQ(::waitpid(child, nullptr, 0), child);
  const std::string stale = ".out.txt.tmp-" + std::to_string(child) + "-0";
  const std::string alive = ".out.txt.tmp-" + std::to_string(::getpid()) + "-99999";
  const std::string other = ".other.txt.tmp-" + std::to_string(child) + "-0";
  for (const std::string& name : {stale, alive, other}) std::ofstream(folder.file(name)) << "old";
  write_atomically(folder.file("out.txt"),
                   [](const std::string& temp_path) { std::ofstream(temp_path) << "new"; });
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{other, alive, "out.txt"}));
}

TEST(AtomicFile, StaleTemporaryIsAlsoRemovedByAnUnnamedWrite) {
  ScratchFolder folder;
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) ::_exit(0);
  ASSERT_EQ(::waitpid(child, nullptr, 0), child);
  const std::string stale = ".out.txt.tmp-" + std::to_string(child) + "-3";
  std::ofstream(folder.file(stale)) << "old";
  write_text_atomically(folder.file("out.txt"), "new");
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"out.txt"});
}

TEST(AtomicFile, FullDiskSaysSo) {
  try {
    throw_write_error("out.png", ENOSPC);
  } catch (const RuntimeFailure& error) {
    EXPECT_STREQ(error.what(), "disk full writing out.png");
  }
  try {
    throw_write_error("out.png", EACCES);
  } catch (const RuntimeFailure& error) {
    EXPECT_STREQ(error.what(), "cannot write out.png: Permission denied");
  }
}

// A real full file system: a 64 KiB tmpfs. Needs mount rights (root); skipped without them.
TEST(AtomicFile, WriteToAFullFileSystemSaysDiskFullAndLeavesNothing) {
  ScratchFolder folder;
  const std::string mount_point = folder.file("small");
  std::filesystem::create_directory(mount_point);
  if (::mount("tmpfs", mount_point.c_str(), "tmpfs", 0, "size=64k") != 0) {
    GTEST_SKIP() << "cannot mount a tmpfs here: " << std::strerror(errno);
  }
  const std::string path = mount_point + "/out.txt";
  std::string message;
  try {
    write_text_atomically(path, std::string(1 << 20, 'x'));
  } catch (const RuntimeFailure& error) {
    message = error.what();
  }
  std::vector<std::string> left;
  for (const auto& entry : std::filesystem::directory_iterator(mount_point)) {
    left.push_back(entry.path().filename().string());
  }
  ::umount(mount_point.c_str());
  EXPECT_EQ(message, "disk full writing " + path);
  EXPECT_TRUE(left.empty());
}

}  // namespace
}  // namespace gloss
