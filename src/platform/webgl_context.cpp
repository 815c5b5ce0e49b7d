#include "platform/webgl_context.h"

#include <emscripten/html5.h>

namespace sl {

std::string createWebGl2Context(const char* selector) {
    EmscriptenWebGLContextAttributes attributes;
    emscripten_webgl_init_context_attributes(&attributes);
    attributes.majorVersion = 2;
    attributes.minorVersion = 0;
    attributes.depth = EM_TRUE;
    attributes.stencil = EM_TRUE;                // the mirror's stencil comparison
    attributes.antialias = EM_FALSE;             // the native renders have none: pixels compare
    attributes.preserveDrawingBuffer = EM_TRUE;  // the tests and the page read the picture back
    EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context =
        emscripten_webgl_create_context(selector, &attributes);
    if (context <= 0)
        return "this browser gives no WebGL 2 context (error " + std::to_string(context) +
               "): try a current Chrome, Firefox or Safari";
    if (emscripten_webgl_make_context_current(context) != EMSCRIPTEN_RESULT_SUCCESS)
        return "the WebGL 2 context could not be made current";
    return "";
}

}  // namespace sl
