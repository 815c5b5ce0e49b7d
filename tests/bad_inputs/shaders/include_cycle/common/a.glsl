#include "common/b.glsl"
