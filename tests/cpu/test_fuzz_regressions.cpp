// Inputs the fuzz harness flagged (tests/fuzz, issue 23), replayed through the same parser as the fuzz
// target that flagged them: each must now fail cleanly, with the documented error and a message naming the
// defect. tests/fuzz/regressions/TARGET/ holds the files; the table below says what each must report.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "app/bench/bench_sweep.h"
#include "app/sidecar.h"
#include "app/ui_script.h"
#include "scenes/gltf_loader.h"

namespace raylab {
namespace {

namespace fs = std::filesystem;

const std::string kRegressions = RAYLAB_SOURCE_DIR "/tests/fuzz/regressions/";

struct Regression {
  const char* target;  // the fuzz target, and the folder
  const char* file;
  const char* fragment;  // the message must contain it
};

const Regression kRegressionFiles[] = {
    {"gltf", "buffer_uri_is_folder.gltf", "File not found : ."},
    {"gltf", "buffer_uri_is_root_folder.gltf", "File not found : /"},
    {"sidecar", "camera_position_beyond_float.json", "camera: 'position' must be finite numbers"},
    {"sidecar", "camera_target_is_position.json", "camera: the target equals the position"},
    {"sidecar", "camera_fov_zero.json", "camera: fov must be between 0.5 and 179.5 degrees"},
    {"sidecar", "camera_up_along_view.json", "camera: 'up' is zero or along the view direction"},
    {"bench_sweep", "axes_multiply.sweep", "the sweep expands to more than 10000 cells"},
    {"bench_sweep", "groups_multiply.sweep", "the sweep expands to more than 10000 cells"},
};

std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// What the fuzz target of `target` runs; returns the message of the documented error, or fails the test.
std::string replay(const std::string& target, const std::string& path) {
  try {
    if (target == "gltf") loadGltf(path);
    else if (target == "sidecar") readSidecar(path);
    else if (target == "ui_script") parseScript(readText(path), path);
    else if (target == "bench_sweep") parseBenchPlan({"--sweep", path});
    else ADD_FAILURE() << "no replay for fuzz target '" << target << "'";
    ADD_FAILURE() << path << " was accepted";
  } catch (const SceneLoadError& e) {
    if (target == "gltf") return e.what();
    ADD_FAILURE() << path << ": SceneLoadError from the " << target << " parser: " << e.what();
  } catch (const UsageError& e) {
    if (target == "sidecar" || target == "bench_sweep") return e.what();
    ADD_FAILURE() << path << ": UsageError from the " << target << " parser: " << e.what();
  } catch (const ScriptError& e) {
    if (target == "ui_script") return e.what();
    ADD_FAILURE() << path << ": ScriptError from the " << target << " parser: " << e.what();
  }
  return {};
}

class FuzzRegression : public testing::TestWithParam<Regression> {};

TEST_P(FuzzRegression, FailsWithTheDocumentedError) {
  std::string path = kRegressions + GetParam().target + "/" + GetParam().file;
  ASSERT_TRUE(fs::exists(path)) << path;
  std::string message = replay(GetParam().target, path);
  EXPECT_NE(message.find(GetParam().fragment), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(Files, FuzzRegression, testing::ValuesIn(kRegressionFiles),
                         [](const testing::TestParamInfo<Regression>& info) {
                           std::string name = std::string(info.param.target) + "_" + fs::path(info.param.file).stem().string();
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

// A file added to a regressions folder but not to the table would go untested.
TEST(FuzzRegressionFiles, EveryFileIsListed) {
  std::set<std::string> listed;
  for (const Regression& r : kRegressionFiles) listed.insert(std::string(r.target) + "/" + r.file);
  size_t files = 0;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(kRegressions)) {
    if (!e.is_regular_file()) continue;
    ++files;
    EXPECT_TRUE(listed.count(fs::relative(e.path(), kRegressions).string())) << e.path();
  }
  EXPECT_EQ(files, listed.size());
}

}  // namespace
}  // namespace raylab
