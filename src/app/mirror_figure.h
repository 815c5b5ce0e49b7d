// `render --figure FILE.png`: the mirror construction seen from above, drawn by gnuplot.
#pragma once

#include <string>

#include "math/mirror_topview.h"

namespace sl {

// Draws `view` (mirrorFigureScript) into the PNG `path`, atomically: gnuplot writes a temporary
// file beside it that is renamed when complete. Returns "" or a one-line reason (gnuplot
// missing or failing, the folder not writable).
std::string writeMirrorFigure(const std::string& path, const MirrorTopView& view);

}  // namespace sl
