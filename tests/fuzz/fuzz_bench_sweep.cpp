// Bench sweep files (`raylab bench --sweep FILE`, app/bench/bench_sweep.h): the file is read and expanded into
// the whole plan, every cell's settings checked, as the bench does before it renders anything. The only
// acceptable failure is UsageError.
#include "app/bench/bench_sweep.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string path = raylab::fuzz::writeInput(data, size, ".sweep");
  try {
    raylab::parseBenchPlan({"--sweep", path});
  } catch (const raylab::UsageError&) {
  }
  return 0;
}
