#version 120
#include "peers/lit_vertex.glsl"
