// A temporary file's path of the running test's own: ctest runs the tests of one suite in parallel processes,
// and a fixed name let two of them overwrite each other's file.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

namespace raylab::test {

inline std::string testTempPath(const std::string& stem, const std::string& extension) {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string name = info ? std::string(info->test_suite_name()) + "_" + info->name() : "none";
  return (std::filesystem::temp_directory_path() /
          (stem + "_" + name + "_" + std::to_string(::getpid()) + extension))
      .string();
}

}  // namespace raylab::test
