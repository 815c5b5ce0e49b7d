// The gnuplot script that draws a MirrorTopView: the mirror seen from above with the viewer,
// the reflected camera and its frustum. Running gnuplot is the caller's business (src/app).
#pragma once

#include <string>

#include "math/mirror_topview.h"

namespace sl {

// A complete gnuplot script (data inline) writing a `width` x `height` PNG to `pngPath`.
// x runs to the right and z down the page, as the scene looks from above with the camera
// behind the viewer. An invalid view draws what it has (mirror, eye, at) and the reason.
std::string mirrorFigureScript(const MirrorTopView& view, const std::string& pngPath,
                               int width = 900, int height = 800);

// One line per value: eye', at', left', right', near', far' (what the figure's title shows).
std::string describeTopView(const MirrorTopView& view);

}  // namespace sl
