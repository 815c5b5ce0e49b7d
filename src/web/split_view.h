// The page's split view and HUD text (web_main.cpp calls these): the window's halves drawn
// into the canvas, and the window's compact HUD as lines the page lays over it.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "lecture/hud_text.h"
#include "lecture/lessons.h"

namespace sl::web {

// Draws `halves` side by side into the canvas (width x height) as the window draws its split
// (window/session_draw.cpp): each with the renderer's camera and light and its own settings, at
// the half's size, the field of view widened so the scene's width fits (math/orbit.h). The
// renderer's values and camera are put back, whatever a half throws.
void drawSplitHalves(Renderer& r, int width, int height, const std::vector<SplitHalf>& halves);

// "NAME\tNAME=VALUE,NAME=VALUE" a half a line.
std::string splitSetsText(const std::vector<SplitHalf>& halves);

// The window's compact HUD for the picture on screen, from the window's own words, one a line,
// each "PLACE\tTEXT": "top" the title (with parameter `selected`) and `lesson` (the lesson
// line, "" for none), "left" and "right" the labels of `halves` (empty: no split), "bottom" the
// view's legend.
std::string hudText(Renderer& r, std::size_t selected, const StudentFolder& folder,
                    const std::string& lesson, const std::vector<SplitHalf>& halves);

}  // namespace sl::web
