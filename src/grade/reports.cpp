#include "grade/reports.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "stages/registry.h"
#include "stages/stage.h"

namespace sl {

namespace {

std::string figureText(double v) {
    if (std::isnan(v)) return "n/a";
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", v);
    return text;
}

std::string seconds3(double s) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", s);
    return text;
}

std::string fixed(double v, int width, int decimals) {
    char text[32];
    if (std::isnan(v))
        std::snprintf(text, sizeof text, "%*s", width, "-");
    else
        std::snprintf(text, sizeof text, "%*.*f", width, decimals, v);
    return text;
}

std::string padded(const std::string& s, std::size_t width) {
    return s.size() >= width ? s + " " : s + std::string(width - s.size(), ' ');
}

std::string points(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", std::round(v * 100) / 100);
    return text;
}

// The length of the valid UTF-8 sequence at `s[i]` that XML 1.0 allows, or 0.
std::size_t xmlCharLength(const std::string& s, std::size_t i) {
    auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    unsigned char b = byte(i);
    if (b < 0x80) return (b >= 0x20 || b == '\t' || b == '\n' || b == '\r') ? 1 : 0;
    std::size_t n = b >= 0xF0 ? 4 : b >= 0xE0 ? 3 : b >= 0xC2 ? 2 : 0;
    if (n == 0 || b > 0xF4 || i + n > s.size()) return 0;
    unsigned code = b & (0x7F >> n);
    for (std::size_t k = 1; k < n; ++k) {
        if ((byte(i + k) & 0xC0) != 0x80) return 0;
        code = (code << 6) | (byte(i + k) & 0x3F);
    }
    bool overlong = (n == 3 && code < 0x800) || (n == 4 && code < 0x10000);
    bool surrogate = code >= 0xD800 && code <= 0xDFFF;
    if (overlong || surrogate || code > 0x10FFFF || code == 0xFFFE || code == 0xFFFF) return 0;
    return n;
}

// Only what every student may see at once: a visible stage's visible rows.
bool seenNow(const StageRecord& st, const RowRecord& row) {
    return st.visibility == "visible" && row.visibility == "visible";
}

}  // namespace

std::string checkTestName(const CheckResult& r) {
    std::string name = r.stage + "/" + r.tree + (r.view.empty() ? "" : "/" + r.view);
    const StageInfo* info = findStage(r.stage);
    if (!info) return name;
    std::string ownScene = info->defaultScene.empty() ? "slides" : info->defaultScene;
    if (!r.scene.empty() && r.scene != ownScene) name += " scene=" + r.scene;
    ParamSet defaults(info->params);
    for (const ParamSpec& p : r.parameters.specs())
        if (r.parameters.text(p.name) != defaults.text(p.name))
            name += " " + p.name + "=" + r.parameters.text(p.name);
    return name;
}

std::string rowName(const RowRecord& row) {
    return checkTestName(row.result);
}

std::string rowOutput(const RowRecord& row) {
    const CheckResult& r = row.result;
    std::ostringstream out;
    out << r.verdict() << ": " << r.message << "\n";
    if (r.expectation.entry)
        out << "expected: " << r.expectation.entry->outcome << " (entry '"
            << r.expectation.entry->label() << "', matched "
            << (r.expectation.exact ? "exactly" : "by the defaults") << ")\n";
    if (r.status != Status::Missing) {
        out << "student files:";
        for (const std::string& f : r.studentFiles) out << " " << f;
        out << (r.studentFiles.empty() ? " none\n" : "\n");
    }
    if (!unjudged(r.status)) {
        out << "figures:";
        for (const auto& [name, value] : r.figureMap())
            out << " " << name << " " << figureText(value);
        out << "\n";
    }
    // Its file name only: the grader's folders are nobody else's business.
    if (r.diffFile.empty())
        out << "diff image: none\n";
    else
        out << "diff image: " << r.diffFile.substr(r.diffFile.find_last_of('/') + 1)
            << " (red: false shadow, blue: false lit, grey: agreement)\n";
    if (!r.note.empty()) out << "note: " << r.note << "\n";
    return out.str();
}

std::string tableHeader() {
    return "stage/tree/view lesson                    false-shadow %  false-lit %  band fs/fl %   "
           "edge mean/p95 px  mirror id % / dB  points  verdict\n";
}

std::string tableLine(const RowRecord& row) {
    const CheckResult& r = row.result;
    const Accuracy& a = r.figures;
    std::string pts = isScored(r.status) ? points(row.points) + "/" + points(row.maxPoints) : "-";
    return padded(checkTestName(r), 40) + fixed(a.falseShadowPct, 9, 2) + "     " +
           fixed(a.falseLitPct, 9, 2) + "    " + fixed(a.falseShadowBandPct, 6, 1) + "/" +
           padded(fixed(a.falseLitBandPct, 5, 1), 6) + "  " + fixed(a.edgeMeanPx, 6, 2) + "/" +
           padded(fixed(a.edgeP95Px, 5, 1), 8) + "  " + fixed(a.mirrorIdPct, 7, 2) + "/" +
           padded(fixed(a.mirrorPsnrDb, 5, 1), 6) + "   " + padded(pts, 8) +
           padded(r.verdict(), 6) + r.message + "\n";
}

std::string stageSummary(const StudentRecord& r) {
    std::ostringstream out;
    char line[640];
    for (const StageRecord& st : r.stages) {
        std::string pts = st.status == Status::NotGraded
                              ? "not graded"
                              : points(st.points) + " / " + points(st.maxPoints);
        std::snprintf(line, sizeof line, "%-16s %-10s %-15s %s\n",
                      (st.stage + "/" + st.tree).c_str(), statusName(st.status), pts.c_str(),
                      st.message.substr(0, 400).c_str());
        out << line;
    }
    if (r.graded())
        std::snprintf(line, sizeof line, "total: %s of %s points\n", points(r.score).c_str(),
                      points(r.maxScore).c_str());
    else
        std::snprintf(line, sizeof line,
                      "total: not graded (%d checks could not be run here: not the submission's; "
                      "rerun)\n",
                      countRows(r).notGraded);
    out << line;
    return out.str();
}

nlohmann::json gradescopeResults(const StudentRecord& r) {
    nlohmann::json tests = nlohmann::json::array();
    int number = 0;
    for (const StageRecord& st : r.stages) {
        ++number;
        int sub = 0;
        for (const RowRecord& row : st.rows) {
            if (!isScored(row.status())) continue;
            const CheckResult& c = row.result;
            nlohmann::json figures = nlohmann::json::object();
            for (const auto& [name, value] : c.figureMap())
                figures[name] = std::isnan(value) ? nlohmann::json() : nlohmann::json(value);
            tests.push_back({{"name", rowName(row)},
                             {"number", std::to_string(number) + "." + std::to_string(++sub)},
                             {"score", row.points},
                             {"max_score", row.maxPoints},
                             {"status", earnsPoints(c.status) ? "passed" : "failed"},
                             {"visibility", row.visibility},
                             {"output", rowOutput(row)},
                             {"tags", {st.stage, c.verdict()}},
                             {"extra_data",
                              {{"verdict", c.verdict()},
                               {"stage_status", statusName(st.status)},
                               {"figures", figures}}}});
        }
    }
    // The top-level output is always visible: visible stages, counting visible rows only.
    std::ostringstream out;
    for (const std::string& n : r.notes) out << "note: " << n << "\n";
    if (!r.error.empty()) out << r.error << "\n";
    int notGraded = 0;
    for (const StageRecord& st : r.stages) {
        int seen = 0, shown = 0;
        double pts = 0, max = 0;
        Status status = Status::Pass;
        for (const RowRecord& row : st.rows) {
            notGraded += row.status() == Status::NotGraded;
            if (!seenNow(st, row)) continue;
            ++seen;
            shown += earnsPoints(row.status());
            pts += row.points;
            max += row.maxPoints;
            status = worst(status, row.status());
        }
        if (seen == 0) continue;
        out << st.stage << "/" << st.tree << ": " << statusName(status) << ", "
            << (status == Status::NotGraded ? "not graded"
                                            : points(pts) + " of " + points(max) + " points")
            << ", " << shown << " of " << seen << " visible checks show the lesson\n";
    }
    if (notGraded > 0)
        out << notGraded
            << " checks could not be run on the grading machine (not your submission's "
               "fault): no score yet; the autograder must be rerun\n";
    if (r.late && r.late->days > 0)
        out << "Handed in " << r.late->handedIn << ", " << r.late->days
            << (r.late->days == 1 ? " day" : " days") << " late: the late policy takes "
            << points(r.late->penalty) << " points off, " << points(r.total()) << " of "
            << points(r.maxScore) << " points\n";
    else if (r.late)
        out << "Handed in " << r.late->handedIn << ": on time\n";
    nlohmann::json results = {{"execution_time", r.seconds},
                              {"output", out.str()},
                              {"visibility", "visible"},
                              {"stdout_visibility", "hidden"},
                              {"tests", tests}};
    if (r.graded()) results["score"] = r.total();  // after the late policy
    return results;
}

std::string xmlEscaped(const std::string& text, bool attribute) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        std::size_t n = xmlCharLength(text, i);
        if (n == 0) {
            out += "\xEF\xBF\xBD";  // U+FFFD
            ++i;
            continue;
        }
        char c = text[i];
        if (n == 1 && c == '&')
            out += "&amp;";
        else if (n == 1 && c == '<')
            out += "&lt;";
        else if (n == 1 && c == '>')
            out += "&gt;";
        else if (n == 1 && c == '"')
            out += "&quot;";
        else if (n == 1 && c == '\'')
            out += "&apos;";
        else if (n == 1 && (c == '\n' || c == '\r' || c == '\t') && attribute)
            out += "&#" + std::to_string(int(c)) + ";";  // else a parser folds them to spaces
        else
            out.append(text, i, n);
        i += n;
    }
    return out;
}

std::string junitXml(const StudentRecord& r) {
    int failures = 0, errors = 0, skipped = 0, tests = 0;
    std::ostringstream cases;
    for (const StageRecord& st : r.stages)
        for (const RowRecord& row : st.rows) {
            const CheckResult& c = row.result;
            ++tests;
            cases << "    <testcase classname=\"shadowlab." << xmlEscaped(st.stage + "/" + st.tree)
                  << "\" name=\"" << xmlEscaped(rowName(row)) << "\" time=\"" << seconds3(c.seconds)
                  << "\">\n"
                  << "      <properties>\n        <property name=\"points\" value=\""
                  << points(row.points) << "\"/>\n        <property name=\"max_points\" value=\""
                  << points(row.maxPoints) << "\"/>\n        <property name=\"visibility\" value=\""
                  << xmlEscaped(row.visibility) << "\"/>\n      </properties>\n";
            const std::string message = xmlEscaped(c.message);
            const std::string output = xmlEscaped(rowOutput(row), false);
            if (c.status == Status::Fail || c.status == Status::Missing) {
                ++failures;
                cases << "      <failure type=\"" << c.verdict() << "\" message=\"" << message
                      << "\">" << output << "</failure>\n";
            } else if (unjudged(c.status)) {
                ++errors;
                cases << "      <error type=\"" << c.verdict() << "\" message=\"" << message
                      << "\">" << output << "</error>\n";
            } else if (c.status == Status::Skip) {
                ++skipped;
                cases << "      <skipped message=\"" << message << "\"/>\n";
            } else {
                cases << "      <system-out>" << output << "</system-out>\n";
            }
            cases << "    </testcase>\n";
        }
    std::ostringstream counts;
    counts << "tests=\"" << tests << "\" failures=\"" << failures << "\" errors=\"" << errors
           << "\" skipped=\"" << skipped << "\" time=\"" << seconds3(r.seconds) << "\"";
    const std::string suite = xmlEscaped(r.assignment + ": " + r.student);
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"" + suite + "\" " +
           counts.str() + ">\n  <testsuite name=\"" + suite + "\" " + counts.str() + ">\n" +
           cases.str() + "  </testsuite>\n</testsuites>\n";
}

}  // namespace sl
