// Scenes as JSON files (format in docs/scene-format.md). Errors name the file, the JSON path
// and, for syntax errors, the line and column.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace sl {

class SceneError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// Parses a scene from JSON text; `origin` names it in error messages.
Scene parseScene(const std::string& text, const std::string& origin);
// Loads a scene: a path (contains '/' or ends in .json) or the name of a built-in scene.
Scene loadScene(const std::string& nameOrPath);
// Names of the built-in scenes (files in <data>/scenes).
std::vector<std::string> builtInScenes();

}  // namespace sl
