#include "common/a.glsl"
