// The speed-accuracy panel: the current strategy's prediction accuracy against its trace and frame time,
// beside the last measured points of the other strategies.
#pragma once

#include "renderer/settings.h"
#include "ui/speed_accuracy_book.h"

namespace raylab {

void drawSpeedAccuracyPanel(const SpeedAccuracyBook& book, const Settings& settings);

}  // namespace raylab
