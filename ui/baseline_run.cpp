#include "ui/baseline_run.h"

namespace raylab {

void BaselineRun::start(const Settings& current) {
  userKernel_ = current.kernel;
  userStrategy_ = current.strategy;
  step_ = Step::Unsorted;
  counted_ = 0;
}

void BaselineRun::restore(Settings& settings) const {
  settings.kernel = userKernel_;
  settings.strategy = userStrategy_;
}

void BaselineRun::cancel(Settings& settings) {
  if (active()) restore(settings);
  step_ = Step::Idle;
}

bool BaselineRun::matches(Step step, const Settings& s) {
  if (step == Step::Unsorted) return s.kernel == Kernel::Wavefront && s.strategy == KeyStrategy::None;
  if (step == Step::Megakernel) return s.kernel == Kernel::Megakernel;
  return false;
}

void BaselineRun::steer(Settings& settings) {
  switch (step_) {
    case Step::Idle: return;
    case Step::Unsorted: settings.kernel = Kernel::Wavefront, settings.strategy = KeyStrategy::None; return;
    case Step::Megakernel: settings.kernel = Kernel::Megakernel; return;
    case Step::Restore: restore(settings), step_ = Step::Idle; return;
  }
}

void BaselineRun::onFrame(const Settings& rendered) {
  if (!matches(step_, rendered) || ++counted_ < kFrames) return;
  counted_ = 0;
  step_ = step_ == Step::Unsorted ? Step::Megakernel : Step::Restore;
}

std::string BaselineRun::status() const {
  if (step_ != Step::Unsorted && step_ != Step::Megakernel) return "";
  return std::string("measuring ") + (step_ == Step::Unsorted ? "unsorted" : "megakernel") + " " +
         std::to_string(counted_) + "/" + std::to_string(kFrames);
}

}  // namespace raylab
