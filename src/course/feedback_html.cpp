#include "course/feedback_html.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "io/files.h"

namespace sl {

using nlohmann::json;

std::string base64(const std::string& bytes) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        unsigned v = (unsigned char)bytes[i] << 16 | (unsigned char)bytes[i + 1] << 8 |
                     (unsigned char)bytes[i + 2];
        for (int k = 18; k >= 0; k -= 6) out += table[(v >> k) & 63];
    }
    if (i < bytes.size()) {
        unsigned v = (unsigned char)bytes[i] << 16;
        if (i + 1 < bytes.size()) v |= (unsigned char)bytes[i + 1] << 8;
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? table[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

namespace {

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
            default:
                out += c;
        }
    }
    return out;
}

std::string num(double v, int decimals = 2) {
    char t[64];
    std::snprintf(t, sizeof t, "%.*f", decimals, v);
    return t;
}

double fig(const json& row, const char* name) {
    if (!row.contains("figures") || !row["figures"].is_object()) return NAN;
    const json& f = row["figures"];
    return f.contains(name) && f[name].is_number() ? f[name].get<double>() : NAN;
}

// An image beside the diff (row["diff"] = X.png; X.render.png, X.truth.png) as a data: URI.
std::string imageUri(const json& row, const std::string& kind) {
    if (!row.contains("diff") || !row["diff"].is_string()) return "";
    std::string path = row["diff"].get<std::string>();
    if (!kind.empty()) path = path.substr(0, path.size() - 4) + "." + kind + ".png";
    std::string bytes;
    if (!readRegularFile(path, 8u << 20, bytes).empty()) return "";
    return "data:image/png;base64," + base64(bytes);
}

const char* kStyle = R"(<style>
body{font-family:sans-serif;margin:1.5em;max-width:1100px;color:#222}
table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #ccc;padding:.25em .5em;text-align:left;vertical-align:top}
.PASS,.full{background:#d7f5d7}.FAIL,.none{background:#f8d4d4}.part{background:#fbefc5}
.MISSING{background:#ddd}.ERROR,.TIMEOUT,.CRASH{background:#e7b0b0}
.pics{display:flex;flex-wrap:wrap;gap:8px}.pics figure{margin:0;width:32%;min-width:200px}
.pics img{width:100%;height:auto;display:block;border:1px solid #888;box-sizing:border-box}
.legend span{display:inline-block;padding:0 .4em;margin-right:.4em;color:#fff}
td.msg{max-width:520px;overflow-wrap:anywhere}
</style>)";

}  // namespace

std::string plainWords(const json& row) {
    std::ostringstream out;
    std::string verdict = row.value("verdict", "");
    if (verdict == "MISSING")
        return "This stage was not in your hand-in, so it could not be graded.";
    if (verdict == "ERROR" || verdict == "TIMEOUT" || verdict == "CRASH")
        return "Your shader could not be run: " + row.value("message", "") +
               ". Fix this first; the stage gets no points until it runs.";
    std::string outcome;
    if (row.contains("expectation") && row["expectation"].is_object())
        outcome = row["expectation"].value("outcome", "");
    double fs = fig(row, "false_shadow_pct"), fl = fig(row, "false_lit_pct"),
           edge = fig(row, "edge_p95_px");
    if (!outcome.empty()) out << "This setting should show: " << outcome << ". ";
    if (!std::isnan(fs))
        out << num(fs, 1) << " % of the surfaces the light reaches are drawn in shadow"
            << (fs > 5 ? " (acne, or shadows too large)" : "") << "; ";
    if (!std::isnan(fl))
        out << num(fl, 1) << " % of the true shadows are drawn lit"
            << (fl > 5 ? " (shadows missing or leaking)" : "") << "; ";
    if (!std::isnan(edge))
        out << "shadow edges are within " << num(edge, 1) << " px of the truth for 95 % of them. ";
    double id = fig(row, "mirror_id_pct");
    if (!std::isnan(id)) out << num(id, 1) << " % of the mirror shows the right object. ";
    out << (verdict == "PASS" ? "That is what this check expects."
                              : "That is not what this check expects.");
    return out.str();
}

std::string studentPage(const json& record) {
    std::ostringstream h;
    std::string student = record.value("student", "");
    h << "<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>" << esc(student)
      << ": " << esc(record.value("assignment", "")) << "</title>" << kStyle << "</head><body>\n";
    h << "<h1>" << esc(record.value("assignment", "")) << "</h1>\n<p><b>" << esc(student)
      << "</b>: " << num(record["score"].get<double>()) << " of "
      << num(record["max_score"].get<double>()) << " points</p>\n";
    if (record["error"].is_string())
        h << "<p class=\"ERROR\">" << esc(record["error"].get<std::string>()) << "</p>\n";
    for (const json& n : record["notes"]) h << "<p>Note: " << esc(n.get<std::string>()) << "</p>\n";
    for (const json& st : record["stages"]) {
        std::string id = st["stage"].get<std::string>() + "/" + st["tree"].get<std::string>();
        std::string status = st["status"];
        h << "<h2 id=\"" << esc(id) << "\">" << esc(id) << ": " << num(st["points"].get<double>())
          << " of " << num(st["max_points"].get<double>()) << " points <span class=\""
          << esc(status) << "\">" << esc(status) << "</span></h2>\n<p>"
          << esc(st.value("message", "")) << "</p>\n";
        int hidden = 0;
        double hiddenPoints = 0;
        const json* shown = nullptr;
        h << "<table><tr><th>view</th><th>setting</th><th>verdict</th><th>points</th><th>in plain "
             "words</th></tr>\n";
        for (const json& row : st["rows"]) {
            if (row.value("visibility", "visible") == "hidden") {
                ++hidden;
                hiddenPoints += row.value("max_points", 0.0);
                continue;
            }
            std::string v = row.value("verdict", "");
            if (!shown || (shown->value("verdict", "") == "PASS" && v != "PASS" &&
                           row.contains("diff") && row["diff"].is_string()))
                shown = &row;
            h << "<tr><td>" << esc(row.value("view", "")) << "</td><td>"
              << esc(row.value("lesson", "")) << "</td><td class=\"" << esc(v) << "\">" << esc(v)
              << "</td><td>" << num(row.value("points", 0.0)) << " / "
              << num(row.value("max_points", 0.0)) << "</td><td class=\"msg\">"
              << esc(plainWords(row)) << "</td></tr>\n";
        }
        h << "</table>\n";
        if (hidden)
            h << "<p>" << hidden << " more checks (" << num(hiddenPoints)
              << " points) are graded but shown after grading is published.</p>\n";
        if (shown && shown->contains("diff") && shown->at("diff").is_string()) {
            std::string mine = imageUri(*shown, "render"), truth = imageUri(*shown, "truth"),
                        diff = imageUri(*shown, "");
            h << "<p>Pictures of the check <b>" << esc(shown->value("view", "")) << " "
              << esc(shown->value("lesson", "")) << "</b>:</p>\n<div class=\"pics\">";
            if (!mine.empty())
                h << "<figure><img alt=\"your picture\" src=\"" << mine
                  << "\"><figcaption>your picture</figcaption></figure>";
            if (!truth.empty())
                h << "<figure><img alt=\"the truth\" src=\"" << truth
                  << "\"><figcaption>the truth (ray traced)</figcaption></figure>";
            if (!diff.empty())
                h << "<figure><img alt=\"the difference\" src=\"" << diff
                  << "\"><figcaption>the difference</figcaption></figure>";
            h << "</div>\n<p class=\"legend\"><span style=\"background:#d22\">red</span>drawn in "
                 "shadow, "
                 "truly lit <span style=\"background:#22d\">blue</span>drawn lit, truly in shadow "
                 "<span style=\"background:#888\">grey</span>agrees with the truth</p>\n";
        }
    }
    h << "</body></html>\n";
    return h.str();
}

namespace {

// What a student's stage shows as its failure, in a few words (the class page counts these).
std::string failureOf(const json& st) {
    std::string status = st["status"];
    if (status == "MISSING") return "not handed in";
    if (status != "graded") return status + ": " + st.value("message", "").substr(0, 120);
    for (const json& row : st["rows"])
        if (row.value("verdict", "") == "FAIL") {
            std::string outcome = row.contains("expectation") && row["expectation"].is_object()
                                      ? row["expectation"].value("outcome", "")
                                      : "";
            return "FAIL at '" + row.value("lesson", "") + "' (expected " + outcome + ")";
        }
    return "";
}

}  // namespace

std::string classPage(const std::string& assignment, const std::vector<json>& records,
                      const std::vector<std::string>& pages) {
    std::ostringstream h;
    h << "<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>" << esc(assignment)
      << ": the class</title>" << kStyle << "</head><body>\n<h1>" << esc(assignment) << "</h1>\n";
    std::vector<std::string> stages;
    if (!records.empty())
        for (const json& st : records.front()["stages"])
            stages.push_back(st["stage"].get<std::string>() + "/" + st["tree"].get<std::string>());
    h << "<p>" << records.size() << " students</p>\n<table><tr><th>student</th>";
    for (const auto& s : stages) h << "<th>" << esc(s) << "</th>";
    h << "<th>total</th></tr>\n";
    std::vector<std::map<std::string, int>> failures(stages.size());
    for (std::size_t k = 0; k < records.size(); ++k) {
        const json& r = records[k];
        h << "<tr><td><a href=\"" << esc(pages[k]) << "\">" << esc(r.value("student", ""))
          << "</a></td>";
        std::size_t i = 0;
        for (const json& st : r["stages"]) {
            double p = st["points"].get<double>(), m = st["max_points"].get<double>();
            std::string status = st["status"];
            std::string cls = status != "graded" ? status
                              : p >= m           ? "full"
                              : p <= 0           ? "none"
                                                 : "part";
            h << "<td class=\"" << esc(cls) << "\">" << (status == "graded" ? num(p) : esc(status))
              << "</td>";
            std::string f = failureOf(st);
            if (!f.empty() && i < failures.size()) ++failures[i][f];
            ++i;
        }
        h << "<td>" << num(r["score"].get<double>()) << " / " << num(r["max_score"].get<double>())
          << "</td></tr>\n";
    }
    h << "</table>\n<h2>Most common failure per "
         "stage</h2>\n<table><tr><th>stage</th><th>failure</th><th>students</th></tr>\n";
    for (std::size_t i = 0; i < stages.size(); ++i) {
        std::string best;
        int count = 0;
        for (const auto& [f, n] : failures[i])
            if (n > count) {
                best = f;
                count = n;
            }
        h << "<tr><td>" << esc(stages[i]) << "</td><td class=\"msg\">"
          << (count ? esc(best) : "none") << "</td><td>" << count << "</td></tr>\n";
    }
    h << "</table>\n</body></html>\n";
    return h.str();
}

std::string gradesCsv(const std::vector<json>& records) {
    auto cell = [](const std::string& s) {
        std::string v = validUtf8(s);
        if (!v.empty() && std::string("=+-@").find(v[0]) != std::string::npos)
            v = "'" + v;  // no formulas
        if (v.find_first_of(",\"\n\r") == std::string::npos) return v;
        std::string out = "\"";
        for (char c : v) out += c == '"' ? std::string("\"\"") : std::string(1, c);
        return out + "\"";
    };
    std::ostringstream out;
    out << "student,status";
    if (!records.empty())
        for (const json& st : records.front()["stages"])
            out << ","
                << cell(st["stage"].get<std::string>() + "/" + st["tree"].get<std::string>());
    out << ",total,max\n";
    for (const json& r : records) {
        out << cell(r.value("student", "")) << "," << cell(r.value("status", ""));
        for (const json& st : r["stages"]) out << "," << num(st["points"].get<double>(), 3);
        out << "," << num(r["score"].get<double>(), 3) << ","
            << num(r["max_score"].get<double>(), 3) << "\n";
    }
    return out.str();
}

}  // namespace sl
