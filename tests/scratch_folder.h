// A folder of the running test's own for the files it writes, shared by every test that writes
// files (one helper, not one per test file).
//
// The folder is <system temporary folder>/voxref-test-<pid>/<suite>.<test> (GoogleTest's names of
// the running test, a parameterized test's '/' made '.'): ctest runs the tests of one binary side
// by side, one process each, and the release and sanitizer builds may run the same test at the same
// time, so the process id and the test's name keep every run apart. It is created empty (whatever
// an earlier process of the same id left is removed first) and removed, with everything in it, when
// the object goes; a test that wants to look at its files after a failure can copy them out.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

#include <gtest/gtest.h>

namespace voxref::test {

class ScratchFolder {
 public:
  ScratchFolder() : path_(folderOfRunningTest()) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchFolder() {
    std::error_code ignored;  // a destructor must not throw; the folder is under the temporary folder
    std::filesystem::remove_all(path_, ignored);
    std::filesystem::remove(path_.parent_path(), ignored);  // the process's folder, once it is empty
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(std::string_view name) const { return path_ / name; }

 private:
  static std::filesystem::path folderOfRunningTest() {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = info ? std::string(info->test_suite_name()) + "." + info->name() : "outside-a-test";
    for (char& c : name)
      if (c == '/') c = '.';
    return std::filesystem::temp_directory_path() / ("voxref-test-" + std::to_string(::getpid())) / name;
  }

  std::filesystem::path path_;
};

}  // namespace voxref::test
