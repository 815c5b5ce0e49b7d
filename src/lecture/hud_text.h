// Words the lecture shows over its picture, with no window and no page: the compact HUD's title
// line, the views' names and legends. The window's HUD (window/hud_content.cpp) and the browser
// page's (web/web_main.cpp, drawn as HTML over the canvas) both take their lines from here.
#pragma once

#include <cstddef>
#include <string>

#include "render/renderer.h"

namespace sl {

// The view's name as the HUD shows it: the mirror stage's `shadow-map` view is its texture.
std::string viewLabel(const StageInfo& stage, ViewMode view);
// One line saying how to read a debug view ("" for the final picture).
std::string viewLegend(const StageInfo& stage, ViewMode view);

// "2 bias": the stage's number (its key) and id.
std::string stageTitle(const Renderer& r);

// The student's folder as the title names it (`--shaders`, or the folder picked in the page):
// "" for none, and the tree its files are for.
struct StudentFolder {
    std::string name;
    GlslTree tree = GlslTree::Core;
};

// The compact HUD's first line with `values` on screen and parameter `selected`:
// "2 bias | core | light-z = standard | h: keys", the student's folder after the tree.
std::string compactTitle(Renderer& r, const ParamSet& values, std::size_t selected,
                         const StudentFolder& folder);

// " (your shader does not read it)" when the student's program does not read the parameter's
// uniform (its name in camelCase: margin-kind, marginKind), so a change that does nothing says
// why; else "".
std::string ignoredMark(Renderer& r, const std::string& param);

}  // namespace sl
