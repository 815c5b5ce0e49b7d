#include "grade/check_formats.h"

#include <cmath>
#include <cstdio>
#include <sstream>

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

bool passed(const CheckResult& r) {
    return !r.error && r.judgement.verdict != Verdict::Fail;
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

std::string checkTestOutput(const CheckResult& r) {
    std::ostringstream out;
    out << r.verdict() << ": " << r.judgement.message << "\n";
    if (r.expectation.entry)
        out << "expected: " << r.expectation.entry->outcome << " (entry '"
            << r.expectation.entry->label() << "', matched "
            << (r.expectation.exact ? "exactly" : "by the defaults") << ")\n";
    if (!r.missing) {
        out << "student files:";
        for (const std::string& f : r.studentFiles) out << " " << f;
        out << (r.studentFiles.empty() ? " none\n" : "\n");
    }
    if (!r.error && !r.missing) {
        out << "figures:";
        for (const auto& [name, value] : r.figureMap())
            out << " " << name << " " << figureText(value);
        out << "\n";
    }
    out << "diff image: " << (r.diffFile.empty() ? "none" : r.diffFile) << "\n";
    if (!r.note.empty()) out << "note: " << r.note << "\n";
    return out.str();
}

nlohmann::json gradescopeJson(const std::vector<CheckResult>& results, double seconds) {
    nlohmann::json tests = nlohmann::json::array();
    double score = 0;
    int pass = 0, fail = 0, errors = 0, skipped = 0, missing = 0;
    for (const CheckResult& r : results) {
        bool skip = !r.error && r.judgement.verdict == Verdict::Skip;
        double max = skip ? 0.0 : 1.0;
        double got = passed(r) && !skip ? 1.0 : 0.0;
        score += got;
        // MISSING: the stage's points are there to be had, and none were handed in.
        (r.error ? errors : r.missing ? missing : skip ? skipped : passed(r) ? pass : fail)++;
        nlohmann::json figures = nlohmann::json::object();
        for (const auto& [name, value] : r.figureMap())
            figures[name] = std::isnan(value) ? nlohmann::json() : nlohmann::json(value);
        tests.push_back(
            {{"name", checkTestName(r)},
             {"score", got},
             {"max_score", max},
             {"status", passed(r) ? "passed" : "failed"},
             {"output", checkTestOutput(r)},
             {"visibility", "visible"},
             {"extra_data",
              {{"verdict", r.verdict()},
               {"figures", figures},
               {"diff", r.diffFile.empty() ? nlohmann::json() : nlohmann::json(r.diffFile)}}}});
    }
    std::ostringstream summary;
    summary << "shadowlab check: " << results.size() << " checks, " << pass << " passed, " << fail
            << " failed, " << missing << " missing, " << errors
            << " errors (ERROR, TIMEOUT, CRASH), " << skipped << " skipped";
    return {{"score", score},
            {"execution_time", static_cast<long>(std::lround(seconds))},
            {"output", summary.str()},
            {"tests", tests}};
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

std::string junitXml(const std::vector<CheckResult>& results, double seconds) {
    int failures = 0, errors = 0, skipped = 0;
    std::ostringstream cases;
    for (const CheckResult& r : results) {
        cases << "    <testcase classname=\"shadowlab.check." << xmlEscaped(r.stage) << "\" name=\""
              << xmlEscaped(checkTestName(r)) << "\" time=\"" << seconds3(r.seconds) << "\">\n";
        const std::string message = xmlEscaped(r.judgement.message);
        const std::string output = xmlEscaped(checkTestOutput(r), false);
        if (r.error) {
            ++errors;
            cases << "      <error type=\"" << r.verdict() << "\" message=\"" << message << "\">"
                  << output << "</error>\n";
        } else if (r.judgement.verdict == Verdict::Fail) {
            ++failures;
            cases << "      <failure type=\"" << r.verdict() << "\" message=\"" << message << "\">"
                  << output << "</failure>\n";
        } else if (r.judgement.verdict == Verdict::Skip) {
            ++skipped;
            cases << "      <skipped message=\"" << message << "\"/>\n";
        } else {
            cases << "      <system-out>" << output << "</system-out>\n";
        }
        cases << "    </testcase>\n";
    }
    std::ostringstream counts;
    counts << "tests=\"" << results.size() << "\" failures=\"" << failures << "\" errors=\""
           << errors << "\" skipped=\"" << skipped << "\" time=\"" << seconds3(seconds) << "\"";
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"shadowlab check\" " +
           counts.str() + ">\n  <testsuite name=\"shadowlab check\" " + counts.str() + ">\n" +
           cases.str() + "  </testsuite>\n</testsuites>\n";
}

}  // namespace sl
