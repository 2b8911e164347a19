#pragma once
// The tools part of the left panel: the tool list and the settings of the chosen tool (brush
// radius, strength and falloff of the tool's own brush, the unified radius, mirror planes, paint
// values on logarithmic sliders, inflate pressure, topology operation).

#include "sculpt/app_model.h"

namespace sculpt::app {

void drawToolSettings(AppModel& model);

}  // namespace sculpt::app
