// The page's reference tracer (docs/web.md): the same program as the page, loaded in a Web
// Worker by trace_worker.js, traces the views the page's check sends (eval/trace_view.h) while
// the page stays free; the page hands each reference to its check by the view's key.
#include <emscripten/emscripten.h>

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "eval/trace_view.h"

namespace {

struct Traced {
    std::string bytes, text;
};

Traced& traced() {
    static Traced t;
    return t;
}

}  // namespace

extern "C" {

// Traces the view `viewJson` (traceViewJson's): {"width", "height", "mirror_id", "pointer",
// "bytes"} (the reference's bytes at pointer, valid until the next call) or {"error"}.
EMSCRIPTEN_KEEPALIVE const char* sl_web_trace(const char* viewJson) {
    Traced& t = traced();
    nlohmann::json out;
    try {
        const sl::ReferenceImage image =
            sl::traceView(sl::traceViewFromJson(nlohmann::json::parse(viewJson)));
        t.bytes = sl::referenceBytes(image);
        out = {{"width", image.width},
               {"height", image.height},
               {"mirror_id", image.mirrorObjectId},
               {"pointer", reinterpret_cast<std::uintptr_t>(t.bytes.data())},
               {"bytes", t.bytes.size()}};
    } catch (const std::exception& e) {
        t.bytes.clear();
        out = {{"error", e.what()}};
    }
    t.text = out.dump();
    return t.text.c_str();
}

}  // extern "C"
