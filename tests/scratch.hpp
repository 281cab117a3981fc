#pragma once
/// A directory of a test's own under the system temporary directory (TMPDIR): unique per
/// run (mkdtemp: two runs at once never share one), removed when the test passes, kept with
/// its path printed when it fails. ci/test runs the tests with a TMPDIR of their own and
/// fails when anything is left in it.

#include <gtest/gtest.h>
#include <stdlib.h>

#include <cctype>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>

namespace mechcheck_test {

class scratch_directory {
 public:
  /// A directory named after the running test (and `tag`); with `whole_run`, one that
  /// outlives the test (a static of a test file) and is kept when any test failed.
  explicit scratch_directory(const std::string& tag = "", bool whole_run = false) : whole_run_(whole_run) {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = "mechcheck-";
    if (info && !whole_run) name += std::string(info->test_suite_name()) + "." + info->name();
    if (!tag.empty()) name += (name.back() == '-' ? "" : "-") + tag;
    for (char& c : name)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '_') c = '_';
    std::string path = (std::filesystem::temp_directory_path() / (name + "-XXXXXX")).string();
    if (!::mkdtemp(path.data())) throw std::runtime_error("scratch_directory: cannot create " + path);
    path_ = path;
  }
  ~scratch_directory() {
    const bool failed = whole_run_ ? ::testing::UnitTest::GetInstance()->failed_test_count() > 0
                                   : ::testing::Test::HasFailure();
    if (failed) {
      std::cerr << "kept for the failure: " << path_.string() << "\n";
      return;
    }
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  scratch_directory(const scratch_directory&) = delete;
  scratch_directory& operator=(const scratch_directory&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
  bool whole_run_ = false;
};

}  // namespace mechcheck_test
