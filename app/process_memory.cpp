#include "app/process_memory.h"

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

namespace raylab {
namespace {

// "VmRSS:\t   81234 kB" -> 81234; nothing when the line does not have that form.
std::optional<uint64_t> kibValue(const std::string& line, const std::string& key) {
  if (line.rfind(key + ":", 0) != 0) return std::nullopt;
  std::istringstream in(line.substr(key.size() + 1));
  uint64_t value = 0;
  std::string unit;
  if (!(in >> value >> unit) || unit != "kB") return std::nullopt;
  return value;
}

}  // namespace

std::optional<ProcessMemory> parseProcStatus(const std::string& statusText) {
  std::istringstream in(statusText);
  std::optional<uint64_t> rss, hwm;
  for (std::string line; std::getline(in, line);) {
    if (auto v = kibValue(line, "VmRSS")) rss = v;
    if (auto v = kibValue(line, "VmHWM")) hwm = v;
  }
  if (!rss) return std::nullopt;
  return ProcessMemory{*rss, hwm.value_or(*rss)};
}

std::optional<ProcessMemory> readProcessMemory() {
  std::ifstream in("/proc/self/status");
  if (!in) return std::nullopt;
  std::stringstream text;
  text << in.rdbuf();
  return parseProcStatus(text.str());
}

std::string memoryReportLine(const std::string& label, uint64_t frame, const std::optional<ProcessMemory>& memory) {
  nlohmann::json line = {{"memory", label}, {"frame", frame}, {"vm_rss_kib", nullptr}, {"vm_hwm_kib", nullptr}};
  if (memory) line["vm_rss_kib"] = memory->residentKiB, line["vm_hwm_kib"] = memory->peakResidentKiB;
  return line.dump();
}

}  // namespace raylab
