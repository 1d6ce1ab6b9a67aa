#include "app/camera_path/path_recovery.h"

#include <algorithm>

#include "app/bench/bench_spread.h"

namespace raylab {

std::vector<CutRecovery> recoveryAfterCuts(const std::vector<std::optional<double>>& error, const std::vector<bool>& cut,
                                           double tolerance) {
  const size_t n = std::min(error.size(), cut.size());
  std::vector<CutRecovery> out;
  for (size_t c = 1; c < n; ++c) {
    if (!cut[c]) continue;
    CutRecovery r;
    r.cutFrame = uint32_t(c);
    for (size_t f = c; f-- > 0;)
      if (error[f]) {
        r.before = error[f];
        break;
      }
    size_t end = c + 1;
    while (end < n && !cut[end]) ++end;
    r.framesSeen = uint32_t(end - c);
    if (r.before)
      for (size_t f = c; f < end; ++f)
        if (error[f] && *error[f] <= *r.before * (1.0 + tolerance)) {
          r.frames = uint32_t(f - c);
          break;
        }
    std::vector<double> secondHalf;
    for (size_t f = c + (end - c) / 2; f < end; ++f)
      if (error[f]) secondHalf.push_back(*error[f]);
    if (!secondHalf.empty()) {
      r.settled = spreadOf(secondHalf).median;
      for (size_t f = c; f < end; ++f)
        if (error[f] && *error[f] <= *r.settled * (1.0 + tolerance)) {
          r.framesToSettle = uint32_t(f - c);
          break;
        }
    }
    out.push_back(r);
  }
  return out;
}

nlohmann::json toJson(const CutRecovery& r) {
  return {{"cut_frame", r.cutFrame},
          {"before", r.before ? nlohmann::json(*r.before) : nlohmann::json(nullptr)},
          {"frames", r.frames ? nlohmann::json(*r.frames) : nlohmann::json(nullptr)},
          {"recovered", r.frames.has_value()},
          {"frames_seen", r.framesSeen},
          {"settled", r.settled ? nlohmann::json(*r.settled) : nlohmann::json(nullptr)},
          {"frames_to_settle", r.framesToSettle ? nlohmann::json(*r.framesToSettle) : nlohmann::json(nullptr)}};
}

}  // namespace raylab
