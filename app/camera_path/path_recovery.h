// Recovery after a cut (issue 37): how many path frames after each cut a learned strategy's prediction error
// takes to come back to within a tolerance (10%) of what it was before the cut, and to within 10% of the level
// it settles at after the cut. The first answers "back where it was" on a path that cuts to a like view; on a
// path alternating two different views the level before a cut is the other view's, so the second (the new
// view's own steady level, the median of the segment's second half: its still-camera value where the segment
// is long enough to settle) is the yardstick there. Pure arithmetic over one replay's per-frame series, so the
// CPU tests check it on synthetic series.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

namespace raylab {

// Within 10% of the value before the cut: the threshold.
inline constexpr double kRecoveryTolerance = 0.10;

struct CutRecovery {
  uint32_t cutFrame = 0;           // the path frame the camera jumped to
  std::optional<double> before;    // the last measured error before the cut (none: nothing measured before it)
  // Frames after the cut frame until the error is back within tolerance: 0 when the cut frame itself is;
  // none when it never is before the next cut or the path's end (or when there is no `before`).
  std::optional<uint32_t> frames;
  uint32_t framesSeen = 0;         // path frames from the cut to the next cut or the end (the window searched)
  // The segment's settled level: the median of its measured errors in its second half (none: none measured),
  // and the frames after the cut until the error is within tolerance of it (none: no settled level).
  std::optional<double> settled;
  std::optional<uint32_t> framesToSettle;
};

// `error[f]`: path frame f's prediction error (none: not measured that frame, e.g. no sorted bounce); `cut[f]`:
// whether frame f is a cut. One entry per cut after frame 0, in path order. A frame without a value neither
// recovers nor breaks the search; "back within" means error <= before * (1 + tolerance) (an error below the
// one before the cut has recovered too).
std::vector<CutRecovery> recoveryAfterCuts(const std::vector<std::optional<double>>& error, const std::vector<bool>& cut,
                                           double tolerance = kRecoveryTolerance);

// {"cut_frame", "before", "frames" (null: never recovered), "recovered", "frames_seen", "settled",
//  "frames_to_settle"}.
nlohmann::json toJson(const CutRecovery& r);

}  // namespace raylab
