// Stage parameters moved to render/stage_params.h (the renderer reads them); kept so stage code
// can go on including this name.
#pragma once

#include "render/stage_params.h"
