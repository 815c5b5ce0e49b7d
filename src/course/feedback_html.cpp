#include "course/feedback_html.h"

#include <cmath>
#include <cstdio>
#include <map>
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
        out << num(f.falseShadowPct, 1) << " % of the surfaces the light reaches are drawn in shadow"
            << (f.falseShadowPct > 5 ? " (acne, or shadows too large)" : "") << "; ";
    if (!std::isnan(f.falseLitPct))
        out << num(f.falseLitPct, 1) << " % of the true shadows are drawn lit"
            << (f.falseLitPct > 5 ? " (shadows missing or leaking)" : "") << "; ";
    if (!std::isnan(f.edgeP95Px))
        out << "shadow edges are within " << num(f.edgeP95Px, 1)
            << " px of the truth for 95 % of them. ";
    if (!std::isnan(f.mirrorIdPct))
        out << num(f.mirrorIdPct, 1) << " % of the mirror shows the right object. ";
    out << (earnsPoints(row.status) ? "That is what this check expects."
                                    : "That is not what this check expects.");
    return out.str();
}

namespace {

// A page is handed back once grades are out (after the due date, published): every row but a
// hidden one (or one of a hidden stage) is shown; hidden rows are counted, never shown.
bool shownToStudent(const StageRecord& st, const RowRecord& row) {
    return st.visibility != "hidden" && row.visibility != "hidden";
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
    h << "<h1>" << esc(record.assignment) << "</h1>\n<p><b>" << esc(record.student) << "</b>: "
      << (record.graded() ? num(record.score) + " of " + num(record.maxScore) + " points"
                          : std::string("not graded yet (the grading machine could not run "
                                        "every check; it will be graded again)"))
      << "</p>\n";
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
              << "</td><td>"
              << (isScored(v) ? num(row.points) + " / " + num(row.maxPoints) : "-")
              << "</td><td class=\"msg\">" << esc(plainWords(row)) << "</td></tr>\n";
        }
        h << "</table>\n";
        if (hidden) h << "<p>" << hidden << " more checks of this stage are hidden.</p>\n";
        if (shown && !shown->result.diffFile.empty()) {
            std::string mine = imageUri(shown->result, "render"),
                        truth = imageUri(shown->result, "truth"),
                        diff = imageUri(shown->result, "");
            h << "<p>Pictures of the check <b>" << esc(shown->result.view) << " "
              << esc(shown->result.lesson) << "</b>:</p>\n<div class=\"pics\">";
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
std::string failureOf(const StageRecord& st) {
    if (st.status == Status::Missing) return "not handed in";
    if (unjudged(st.status)) return std::string(statusName(st.status)) + ": " + st.message.substr(0, 120);
    for (const RowRecord& row : st.rows)
        if (row.status() == Status::Fail) {
            std::string outcome =
                row.result.expectation.entry ? row.result.expectation.entry->outcome : "";
            return "FAIL at '" + row.result.lesson + "' (expected " + outcome + ")";
        }
    return "";
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
        for (const StageRecord& st : records.front().stages) stages.push_back(st.stage + "/" + st.tree);
    h << "<p>" << records.size() << " students</p>\n<table><tr><th>student</th>";
    for (const auto& s : stages) h << "<th>" << esc(s) << "</th>";
    h << "<th>total</th></tr>\n";
    std::vector<std::map<std::string, int>> failures(stages.size());
    for (std::size_t k = 0; k < records.size(); ++k) {
        const StudentRecord& r = records[k];
        h << "<tr><td><a href=\"" << esc(pages[k]) << "\">" << esc(r.student) << "</a></td>";
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
    static const char* const kFormulaStarts[] = {"=",  "+",  "-",  "@",  "\t", "\r",
                                                "\xEF\xBC\x9D", "\xEF\xBC\x8B", "\xEF\xBC\x8D",
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
    out << "student,status";
    if (!records.empty())
        for (const StageRecord& st : records.front().stages)
            out << "," << csvCell(st.stage + "/" + st.tree);
    out << ",total,max,not_graded\r\n";
    for (const StudentRecord& r : records) {
        out << csvCell(r.student) << "," << csvCell(statusName(r.status()));
        std::string reasons;
        for (const StageRecord& st : r.stages) {
            // A stage that is not graded has no points, not 0: an empty cell, the reason last.
            if (st.status == Status::NotGraded) {
                out << ",";
                reasons += (reasons.empty() ? "" : "; ") + st.stage + "/" + st.tree + ": " +
                           st.message;
            } else {
                out << "," << num(st.points, 3);
            }
        }
        if (r.graded())
            out << "," << num(r.score, 3) << "," << num(r.maxScore, 3) << ",";
        else
            out << ",,," << csvCell(reasons);
        out << "\r\n";
    }
    return out.str();
}

}  // namespace sl
