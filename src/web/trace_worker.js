// The page's reference tracer (docs/web.md): the page's own program (shadowlab.js) in a Web
// Worker, tracing each view the page's check sends (sl_web_trace, src/web/trace_worker.cpp) and
// sending its reference back as bytes, so the page stays free while the truth is traced.
var Module = { onRuntimeInitialized: () => postMessage({ ready: true }) };
importScripts("shadowlab.js");
onmessage = event => {
  const { key, view } = event.data;
  const out = JSON.parse(Module.ccall("sl_web_trace", "string", ["string"], [JSON.stringify(view)]));
  if (out.error) { postMessage({ key, error: out.error }); return; }
  const bytes = Module.HEAPU8.slice(out.pointer, out.pointer + out.bytes).buffer;
  postMessage({ key, width: out.width, height: out.height, mirror_id: out.mirror_id, bytes }, [bytes]);
};
