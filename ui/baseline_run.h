// "Measure baselines": the speed-accuracy panel asks, through the Settings it edits (never the renderer), for
// a few frames of the unsorted wavefront and then of the megakernel, and then gives the user's own method
// back. Plain C++: tests/cpu/test_speed_accuracy_book.cpp runs it against the book.
#pragma once

#include <cstdint>
#include <string>

#include "renderer/settings/settings.h"

namespace raylab {

class BaselineRun {
 public:
  static constexpr uint32_t kFrames = 6;  // frames measured per baseline

  // Starts from the user's settings (their kernel and strategy come back at the end).
  void start(const Settings& current);
  void cancel(Settings& settings);  // back to the user's method now
  bool active() const { return step_ != Step::Idle; }
  // Before the panels draw, every UI frame: sets the kernel and strategy the current step measures, or,
  // once the last one is done, the user's own.
  void steer(Settings& settings);
  // Every finished frame, with the settings it was rendered with: frames rendered before the switch took
  // effect do not count.
  void onFrame(const Settings& rendered);
  std::string status() const;  // "measuring unsorted 2/6", "" when idle

 private:
  enum class Step { Idle, Unsorted, Megakernel, Restore };
  static bool matches(Step step, const Settings& s);
  void restore(Settings& settings) const;
  Step step_ = Step::Idle;
  uint32_t counted_ = 0;
  Kernel userKernel_ = Kernel::Wavefront;
  KeyStrategy userStrategy_ = KeyStrategy::None;
};

}  // namespace raylab
