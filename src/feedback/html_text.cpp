#include "feedback/html_text.h"

#include <cstdio>

#include "io/files.h"

namespace sl {

std::string esc(const std::string& raw) {
    std::string s = validUtf8(raw), out;
    for (char c : s) {
        switch (c) {
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '&':
                out += "&amp;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&#39;";
                break;
            default:  // ESC, BEL and the other controls are no text (HTML has no form for them)
                out += (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t') || c == 0x7f
                           ? '?'
                           : c;
        }
    }
    return out;
}

std::string numText(double v, int decimals) {
    char t[64];
    std::snprintf(t, sizeof t, "%.*f", decimals, v);
    return t;
}

const char* const kStyle = R"(<style>
body{font-family:sans-serif;margin:1.5em;max-width:1100px;color:#222}
table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #ccc;padding:.25em .5em;text-align:left;vertical-align:top}
.PASS,.full{background:#d7f5d7}.FAIL,.none{background:#f8d4d4}.part{background:#fbefc5}
.MISSING,.NOT{background:#ddd}.ERROR,.TIMEOUT,.CRASH{background:#e7b0b0}
.pics{display:flex;flex-wrap:wrap;gap:8px}.pics figure{margin:0;width:32%;min-width:200px}
.pics img{width:100%;height:auto;display:block;border:1px solid #888;box-sizing:border-box}
.legend span{display:inline-block;padding:0 .4em;margin-right:.4em;color:#fff}
td.msg{max-width:520px;overflow-wrap:anywhere}
</style>)";

}  // namespace sl
