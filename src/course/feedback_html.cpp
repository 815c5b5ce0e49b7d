#include "course/feedback_html.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <regex>
#include <set>
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

// An image beside the diff (X.png; X.render.png, X.truth.png) as a data: URI.
std::string imageUri(const CheckResult& row, const std::string& kind) {
    if (row.diffFile.empty()) return "";
    std::string path = row.diffFile;
    if (!kind.empty()) path = path.substr(0, path.size() - 4) + "." + kind + ".png";
    std::string bytes;
    if (!readRegularFile(path, 8u << 20, bytes).empty()) return "";
    return "data:image/png;base64," + base64(bytes);
}

const char* kStyle = R"(<style>
body{font-family:sans-serif;margin:1.5em;max-width:1100px;color:#222}
table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #ccc;padding:.25em .5em;text-align:left;vertical-align:top}
.PASS,.full{background:#d7f5d7}.FAIL,.none{background:#f8d4d4}.part{background:#fbefc5}
.MISSING,.NOT{background:#ddd}.ERROR,.TIMEOUT,.CRASH{background:#e7b0b0}
.pics{display:flex;flex-wrap:wrap;gap:8px}.pics figure{margin:0;width:32%;min-width:200px}
.pics img{width:100%;height:auto;display:block;border:1px solid #888;box-sizing:border-box}
.legend span{display:inline-block;padding:0 .4em;margin-right:.4em;color:#fff}
td.msg{max-width:520px;overflow-wrap:anywhere}
</style>)";

// A bound as a judge writes it (">= 32", "<= 5", "in [0, 5]") in words.
std::string boundInWords(const std::string& bound) {
    if (bound.rfind(">= ", 0) == 0) return "at least " + bound.substr(3);
    if (bound.rfind("<= ", 0) == 0) return "at most " + bound.substr(3);
    std::smatch m;
    static const std::regex range(R"(in \[(\S+), (\S+)\])");
    if (std::regex_match(bound, m, range)) return "between " + m[1].str() + " and " + m[2].str();
    return bound;
}

// One failing figure in plain words: what it measures, its value and the bound it missed.
std::string figureInWords(const std::string& figure, const std::string& value,
                          const std::string& bound) {
    static const std::map<std::string, std::pair<std::string, std::string>> kWords = {
        {"false_shadow_pct", {"the surfaces the light reaches drawn in shadow", " %"}},
        {"false_lit_pct", {"the true shadows drawn lit", " %"}},
        {"false_shadow_band_pct", {"false shadow near the shadow edges", " %"}},
        {"false_lit_band_pct", {"false light near the shadow edges", " %"}},
        {"edge_mean_px", {"the mean distance of your shadow edges from the truth", " px"}},
        {"edge_p95_px", {"the distance within which 95 % of your shadow edges lie", " px"}},
        {"dark_without_caster_pct", {"the picture drawn dark where nothing casts a shadow", " %"}},
        {"false_shadow_speckle_pct", {"speckled false shadow (acne)", " %"}},
        {"shadow_level_off_pct", {"the shadows at the wrong darkness", " %"}},
        {"lit_light_lost_pct", {"the lit surfaces that lost light", " %"}},
        {"lit_too_bright_pct", {"the lit surfaces drawn too bright", " %"}},
        {"mirror_id_pct", {"the mirror showing the right object", " %"}},
        {"mirror_psnr_db", {"your mirror's PSNR against the exact (stencil) reflection", " dB"}}};
    auto it = kWords.find(figure);
    std::string what = it == kWords.end() ? figure : it->second.first;
    std::string unit = it == kWords.end() ? "" : it->second.second;
    return what + " is " + value + unit + ", and should be " + boundInWords(bound) + unit;
}

// The figures a judge's message names as failing ("mirror_psnr_db 12.5 not >= 32", possibly
// with widened bounds in a displaced view), each in plain words.
std::vector<std::string> failedFigures(const std::string& message) {
    static const std::regex failing(R"(([a-z_0-9]+) (\S+) not (>= \S+|<= \S+|in \[\S+, \S+\]))");
    std::vector<std::string> out;
    for (std::sregex_iterator it(message.begin(), message.end(), failing), end; it != end; ++it) {
        std::string bound = (*it)[3].str();
        if (!bound.empty() && bound.back() == ',') bound.pop_back();
        out.push_back(figureInWords((*it)[1].str(), (*it)[2].str(), bound));
    }
    return out;
}

}  // namespace

std::string plainWords(const RowRecord& rr) {
    const CheckResult& row = rr.result;
    std::ostringstream out;
    switch (row.status) {
        case Status::Missing:
            return "This stage was not in your hand-in, so it could not be graded.";
        case Status::NotGraded:
            return "This check could not be run on the grading machine. That is not your "
                   "submission's fault; it will be graded again.";
        case Status::Error:
        case Status::Timeout:
        case Status::Crash:
            return "Your shader could not be run: " + row.message +
                   ". Fix this first; the stage gets no points until it runs.";
        default:
            break;
    }
    if (row.expectation.entry)
        out << "This setting should show: " << row.expectation.entry->outcome << ". ";
    const Accuracy& f = row.figures;
    if (!std::isnan(f.falseShadowPct))
        out << num(f.falseShadowPct, 1)
            << " % of the surfaces the light reaches are drawn in shadow"
            << (f.falseShadowPct > 5 ? " (acne, or shadows too large)" : "") << "; ";
    if (!std::isnan(f.falseLitPct))
        out << num(f.falseLitPct, 1) << " % of the true shadows are drawn lit"
            << (f.falseLitPct > 5 ? " (shadows missing or leaking)" : "") << "; ";
    if (!std::isnan(f.edgeP95Px))
        out << "shadow edges are within " << num(f.edgeP95Px, 1)
            << " px of the truth for 95 % of them. ";
    if (!std::isnan(f.mirrorIdPct))
        out << num(f.mirrorIdPct, 1) << " % of the mirror shows the right object. ";
    if (earnsPoints(row.status)) {
        out << "That is what this check expects.";
        return out.str();
    }
    out << "That is not what this check expects";
    std::vector<std::string> failed = failedFigures(row.message);
    for (std::size_t i = 0; i < failed.size(); ++i) out << (i == 0 ? ": " : "; ") << failed[i];
    out << ".";
    return out.str();
}

namespace {

// A page is handed back once grades are out (after the due date, published): every row but a
// hidden one (or one of a hidden stage) is shown; hidden rows are counted, never shown.
bool shownToStudent(const StageRecord& st, const RowRecord& row) {
    return st.visibility != "hidden" && row.visibility != "hidden";
}

// The three pictures of a row's check, side by side, with the legend of its difference picture
// (the mirror's is its difference from our exact stencil reflection).
std::string picturesOf(const CheckResult& row) {
    const bool mirror = row.stage == "mirror";
    const std::pair<const char*, std::string> pictures[] = {
        {"your picture", imageUri(row, "render")},
        {mirror ? "the exact reflection (stencil method, our shaders)" : "the truth (ray traced)",
         imageUri(row, "truth")},
        {mirror ? "the difference inside the mirror" : "the difference", imageUri(row, "")}};
    std::ostringstream h;
    h << "<p>Pictures of the check <b>" << esc(row.view) << " " << esc(row.lesson)
      << "</b>:</p>\n<div class=\"pics\">";
    for (const auto& [caption, uri] : pictures)
        if (!uri.empty())
            h << "<figure><img alt=\"" << caption << "\" src=\"" << uri << "\"><figcaption>"
              << caption << "</figcaption></figure>";
    h << "</div>\n<p class=\"legend\">";
    if (mirror)
        h << "<span style=\"background:#d22\">red</span>your mirror differs from the exact "
             "reflection (the brighter, the larger) <span style=\"background:#000\">black</span>"
             "agrees <span style=\"background:#888\">grey</span>outside the mirror</p>\n";
    else
        h << "<span style=\"background:#d22\">red</span>drawn in shadow, truly lit "
             "<span style=\"background:#22d\">blue</span>drawn lit, truly in shadow "
             "<span style=\"background:#888\">grey</span>agrees with the truth</p>\n";
    return h.str();
}

// The late policy's line: when the hand-in came and what it cost.
std::string lateLine(const LateRecord& late, const StudentRecord& r) {
    std::ostringstream h;
    h << "<p>Handed in " << esc(late.handedIn) << " (from " << esc(late.source) << "): ";
    if (late.days == 0)
        h << "on time.";
    else
        h << num(late.minutes / 60.0, 1) << " hours late, " << late.days
          << (late.days == 1 ? " day" : " days")
          << " charged by the late policy: " << num(late.penalty) << " points off, "
          << num(r.total()) << " of " << num(r.maxScore) << " points after the penalty.";
    h << "</p>\n";
    return h.str();
}

std::string pointsOf(double points, double max, Status status) {
    return status == Status::NotGraded ? "not graded" : num(points) + " of " + num(max) + " points";
}

}  // namespace

std::string studentPage(const StudentRecord& record) {
    std::ostringstream h;
    h << "<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>"
      << esc(record.student) << ": " << esc(record.assignment) << "</title>" << kStyle
      << "</head><body>\n";
    h << "<h1>" << esc(record.assignment) << "</h1>\n<p><b>" << esc(record.student) << "</b>"
      << (record.roster ? " (" + esc(record.roster->name) + ", " + esc(record.roster->id) + ")"
                        : std::string())
      << ": "
      << (record.graded() ? num(record.score) + " of " + num(record.maxScore) + " points"
                          : std::string("not graded yet (the grading machine could not run "
                                        "every check; it will be graded again)"))
      << "</p>\n";
    if (record.late) h << lateLine(*record.late, record);
    for (const Adjustment& a : record.adjustments)
        h << "<p>Adjusted by your teaching staff: " << (a.points >= 0 ? "+" : "") << num(a.points)
          << " points on " << esc(a.stage) << ": " << esc(a.reason) << "</p>\n";
    if (!record.adjustments.empty() && record.graded())
        h << "<p>Your total: " << num(record.total()) << " of " << num(record.maxScore)
          << " points.</p>\n";
    if (!record.error.empty()) h << "<p class=\"ERROR\">" << esc(record.error) << "</p>\n";
    for (const std::string& n : record.notes) h << "<p>Note: " << esc(n) << "</p>\n";
    for (const StageRecord& st : record.stages) {
        std::string id = st.stage + "/" + st.tree;
        std::string status = statusName(st.status);
        h << "<h2 id=\"" << esc(id) << "\">" << esc(id) << ": "
          << pointsOf(st.points, st.maxPoints, st.status) << " <span class=\"" << esc(status)
          << "\">" << esc(status) << "</span></h2>\n<p>"
          << esc(st.status == Status::NotGraded
                     ? "The grading machine could not run this stage. That is not your "
                       "submission's fault; it will be graded again."
                     : st.message)
          << "</p>\n";
        int hidden = 0;
        const RowRecord* shown = nullptr;
        h << "<table><tr><th>view</th><th>setting</th><th>verdict</th><th>points</th><th>in plain "
             "words</th></tr>\n";
        for (const RowRecord& row : st.rows) {
            if (!shownToStudent(st, row)) {
                ++hidden;
                continue;
            }
            const Status v = row.status();
            if (!shown || (shown->status() == Status::Pass && v != Status::Pass &&
                           !row.result.diffFile.empty()))
                shown = &row;
            h << "<tr><td>" << esc(row.result.view) << "</td><td>" << esc(row.result.lesson)
              << "</td><td class=\"" << esc(statusName(v)) << "\">" << esc(statusName(v))
              << "</td><td>" << (isScored(v) ? num(row.points) + " / " + num(row.maxPoints) : "-")
              << "</td><td class=\"msg\">" << esc(plainWords(row)) << "</td></tr>\n";
        }
        h << "</table>\n";
        if (hidden) h << "<p>" << hidden << " more checks of this stage are hidden.</p>\n";
        if (shown && !shown->result.diffFile.empty()) h << picturesOf(shown->result);
    }
    h << "</body></html>\n";
    return h.str();
}

namespace {

// What a student's stage shows as its failure, in a few words (the class page counts these).
std::string failureOf(const StageRecord& st) {
    if (st.status == Status::Missing) return "not handed in";
    if (unjudged(st.status))
        return std::string(statusName(st.status)) + ": " + st.message.substr(0, 120);
    for (const RowRecord& row : st.rows)
        if (row.status() == Status::Fail) {
            std::string outcome =
                row.result.expectation.entry ? row.result.expectation.entry->outcome : "";
            return "FAIL at '" + row.result.lesson + "' (expected " + outcome + ")";
        }
    return "";
}

// The copy flags of the class (course/copy_flags.h), one row per student and file: for the
// instructor to look at, never a score, never on a student's page.
std::string copyFlagsTable(const std::vector<StudentRecord>& records,
                           const std::vector<std::string>& pages) {
    std::ostringstream rows;
    for (std::size_t k = 0; k < records.size(); ++k)
        for (const std::string& f : records[k].flags)
            rows << "<tr><td><a href=\"" << esc(pages[k]) << "\">" << esc(records[k].student)
                 << "</a></td><td class=\"msg\">" << esc(f) << "</td></tr>\n";
    if (rows.str().empty()) return "";
    return "<h2>Possible copies (for the instructor: not a score)</h2>\n"
           "<table><tr><th>student</th><th>file and what it equals</th></tr>\n" +
           rows.str() + "</table>\n";
}

}  // namespace

std::string classPage(const std::string& assignment, const std::vector<StudentRecord>& records,
                      const std::vector<std::string>& pages,
                      const std::vector<std::string>& skipped) {
    std::ostringstream h;
    h << "<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>" << esc(assignment)
      << ": the class</title>" << kStyle << "</head><body>\n<h1>" << esc(assignment) << "</h1>\n";
    std::vector<std::string> stages;
    if (!records.empty())
        for (const StageRecord& st : records.front().stages)
            stages.push_back(st.stage + "/" + st.tree);
    h << "<p>" << records.size() << " students</p>\n<table><tr><th>student</th>";
    for (const auto& s : stages) h << "<th>" << esc(s) << "</th>";
    h << "<th>total</th></tr>\n";
    std::vector<std::map<std::string, int>> failures(stages.size());
    for (std::size_t k = 0; k < records.size(); ++k) {
        const StudentRecord& r = records[k];
        h << "<tr><td><a href=\"" << esc(pages[k]) << "\">" << esc(r.student) << "</a>"
          << (r.roster ? " " + esc(r.roster->name) : std::string()) << "</td>";
        std::size_t i = 0;
        for (const StageRecord& st : r.stages) {
            double p = st.points, m = st.maxPoints;
            const bool scored = !unjudged(st.status);
            std::string cls = st.status == Status::NotGraded ? "NOT"
                              : !scored                      ? statusName(st.status)
                              : p >= m                       ? "full"
                              : p <= 0                       ? "none"
                                                             : "part";
            h << "<td class=\"" << esc(cls) << "\">"
              << (scored ? num(p) : esc(statusName(st.status))) << "</td>";
            std::string f = failureOf(st);
            if (!f.empty() && i < failures.size()) ++failures[i][f];
            ++i;
        }
        h << "<td>" << (r.graded() ? num(r.score) + " / " + num(r.maxScore) : "not graded")
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
    h << "</table>\n";
    // The source rules' findings (possible gaming, a method not written): for the instructor,
    // never a score by themselves, never on a student's page.
    std::ostringstream notes;
    for (std::size_t k = 0; k < records.size(); ++k)
        for (const StageRecord& st : records[k].stages) {
            std::set<std::string> seen;
            for (const RowRecord& row : st.rows)
                for (const std::string& n : row.result.sourceNotes)
                    if (seen.insert(n).second)
                        notes << "<tr><td><a href=\"" << esc(pages[k]) << "\">"
                              << esc(records[k].student) << "</a></td><td>"
                              << esc(st.stage + "/" + st.tree) << "</td><td class=\"msg\">"
                              << esc(n) << "</td></tr>\n";
        }
    if (!notes.str().empty())
        h << "<h2>Notes from the source rules (for the instructor: not a score)</h2>\n"
             "<table><tr><th>student</th><th>stage</th><th>note</th></tr>\n"
          << notes.str() << "</table>\n";
    h << copyFlagsTable(records, pages);
    if (!skipped.empty()) {
        h << "<h2>Left out of the class folder (not hand-ins)</h2>\n<ul>\n";
        for (const std::string& s : skipped) h << "<li>" << esc(s) << "</li>\n";
        h << "</ul>\n";
    }
    h << "</body></html>\n";
    return h.str();
}

std::string csvCell(const std::string& s) {
    std::string v = validUtf8(s);
    // A spreadsheet evaluates a cell that starts with = + - @, a TAB or a CR, or their
    // full-width forms (U+FF1D = , U+FF0B + , U+FF0D - , U+FF20 @): prefixed, never a formula
    // (OWASP's CSV injection rule).
    static const char* const kFormulaStarts[] = {
        "=",           "+", "-", "@", "\t", "\r", "\xEF\xBC\x9D", "\xEF\xBC\x8B", "\xEF\xBC\x8D",
        "\xEF\xBC\xA0"};
    for (const char* start : kFormulaStarts)
        if (v.rfind(start, 0) == 0) {
            v = "'" + v;
            break;
        }
    // RFC 4180: a field holding a comma, a quote or a line break is quoted, quotes doubled.
    if (v.find_first_of(",\"\n\r") == std::string::npos) return v;
    std::string out = "\"";
    for (char c : v) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string gradesCsv(const std::vector<StudentRecord>& records) {
    std::ostringstream out;
    out << "student,id,name,email,status";
    if (!records.empty())
        for (const StageRecord& st : records.front().stages)
            out << "," << csvCell(st.stage + "/" + st.tree);
    out << ",adjustments,late_penalty,total,max,not_graded\r\n";
    for (const StudentRecord& r : records) {
        const RosterInfo who = r.roster.value_or(RosterInfo{});
        out << csvCell(r.student) << "," << csvCell(who.id) << "," << csvCell(who.name) << ","
            << csvCell(who.email) << "," << csvCell(statusName(r.status()));
        std::string reasons;
        for (const StageRecord& st : r.stages) {
            // A stage that is not graded has no points, not 0: an empty cell, the reason last.
            if (st.status == Status::NotGraded) {
                out << ",";
                reasons +=
                    (reasons.empty() ? "" : "; ") + st.stage + "/" + st.tree + ": " + st.message;
            } else {
                out << "," << num(st.points, 3);
            }
        }
        double adjusted = 0;
        for (const Adjustment& a : r.adjustments) adjusted += a.points;
        out << "," << (r.adjustments.empty() ? "" : num(adjusted, 3)) << ","
            << (r.late ? num(r.late->penalty, 3) : "");
        if (r.graded())
            out << "," << num(r.total(), 3) << "," << num(r.maxScore, 3) << ",";
        else
            out << ",,," << csvCell(reasons);
        out << "\r\n";
    }
    return out.str();
}

}  // namespace sl
