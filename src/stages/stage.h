// A stage's view of the framework: the interface the renderer calls (render/stage_interface.h),
// the parameters it declares and what a stage file defines (StageDefinition, stages/registry.h).
// A new stage includes this header.
#pragma once

#include "render/stage_interface.h"
#include "stages/registry.h"
