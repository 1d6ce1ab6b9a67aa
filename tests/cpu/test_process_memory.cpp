// Resident memory as the soak reads it (app/process_memory.h).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/process_memory.h"

namespace raylab {
namespace {

TEST(ProcessMemory, ParsesProcStatus) {
  const char* status =
      "Name:\traylab\nVmPeak:\t  900000 kB\nVmHWM:\t   91234 kB\nVmRSS:\t   81234 kB\nThreads:\t4\n";
  auto m = parseProcStatus(status);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->residentKiB, 81234u);
  EXPECT_EQ(m->peakResidentKiB, 91234u);
  EXPECT_FALSE(parseProcStatus("Name:\tx\nVmRSS:\tlots\n"));
  EXPECT_FALSE(parseProcStatus("VmRSS:\t12 MB\n"));
  EXPECT_FALSE(parseProcStatus(""));
}

TEST(ProcessMemory, ReadsThisProcessAndReportsOneJsonLine) {
  auto m = readProcessMemory();
  ASSERT_TRUE(m) << "no /proc/self/status";
  EXPECT_GT(m->residentKiB, 100u);  // a running test binary holds more than 100 KiB
  EXPECT_GE(m->peakResidentKiB, m->residentKiB);
  std::string line = memoryReportLine("warm", 500, m);
  EXPECT_EQ(line.find('\n'), std::string::npos);
  auto j = nlohmann::json::parse(line);
  EXPECT_EQ(j["memory"], "warm");
  EXPECT_EQ(j["frame"], 500);
  EXPECT_EQ(j["vm_rss_kib"], m->residentKiB);
  EXPECT_TRUE(nlohmann::json::parse(memoryReportLine("end", 1, std::nullopt))["vm_rss_kib"].is_null());
}

}  // namespace
}  // namespace raylab
