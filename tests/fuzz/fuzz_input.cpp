#include "tests/fuzz/fuzz_input.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace raylab::fuzz {
namespace {

// One folder per process: libFuzzer's -jobs/-workers run several processes side by side.
struct InputFolder {
  std::filesystem::path path;
  InputFolder() {
    std::string base = (std::filesystem::temp_directory_path() / "raylab-fuzz-XXXXXX").string();
    if (mkdtemp(base.data()) == nullptr) throw std::runtime_error("fuzz: cannot make a temporary folder");
    path = base;
  }
  ~InputFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
};

}  // namespace

std::string writeInput(const uint8_t* data, size_t size, const std::string& extension) {
  static InputFolder folder;
  std::string file = (folder.path / ("input" + extension)).string();
  std::FILE* f = std::fopen(file.c_str(), "wb");
  if (f == nullptr || (size > 0 && std::fwrite(data, 1, size, f) != size) || std::fclose(f) != 0) {
    std::perror(file.c_str());
    std::abort();  // the harness itself failed: not a finding in the parser, but it must not pass silently
  }
  return file;
}

}  // namespace raylab::fuzz
