// Where the program finds its data (shader trees, scenes, slide examples, expectations): an
// installed copy, or the source tree it was built from.
#pragma once

#include <string>

namespace sl {

// The folder holding shaders_core/, shaders_legacy/, scenes/ and slides_examples/:
// $SHADOWLAB_DATA_DIR, else ../share/shadowlab beside the executable (an installed copy), else
// the source tree the program was built from (unless $SHADOWLAB_NO_SOURCE_DIR is set).
std::string dataDir();

}  // namespace sl
