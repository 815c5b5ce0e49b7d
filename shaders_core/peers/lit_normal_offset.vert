#version 330 core
#include "peers/lit_vertex.glsl"
