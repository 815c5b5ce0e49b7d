// The renderer's exceptions as a bounded worker carries them to its parent (sandbox/worker.h):
// ShaderError "shader", SceneError "scene", ExpectationError "expectation", each thrown again
// with its type in the parent, so `render`, `check` and the window end as they would without
// the worker.
#pragma once

#include "sandbox/worker.h"

namespace sl {

const JobErrorKinds& renderJobErrors();

}  // namespace sl
