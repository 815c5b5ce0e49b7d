// A stage's view of the framework: the interface the renderer calls (render/stage_interface.h)
// and the parameters it declares. A new stage includes this header.
#pragma once

#include "render/stage_interface.h"
