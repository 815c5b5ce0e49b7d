#include "course/student_grade.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "grade/check_formats.h"

namespace sl {

using nlohmann::json;

std::vector<StagePlan> planStudent(const Assignment& a, const StudentWork& s,
                                   std::optional<std::uint64_t> seed) {
    std::vector<StagePlan> out;
    for (const AssignmentStage* st : a.due()) {
        StagePlan p;
        p.stage = st;
        for (const std::string& f : st->files)
            if (!s.has(f)) p.missingFiles.push_back(f);
        p.rows = planStage(a, *st, p.missingFiles.empty() ? s.overlay : "", seed);
        out.push_back(std::move(p));
    }
    return out;
}

std::vector<std::vector<CheckCase>> checksOf(const std::vector<StagePlan>& plan) {
    std::vector<std::vector<CheckCase>> out;
    for (const StagePlan& p : plan) {
        if (!p.missingFiles.empty()) continue;
        out.emplace_back();
        for (const RowPlan& r : p.rows) out.back().push_back(r.check);
    }
    return out;
}

namespace {

std::string withoutPrefix(std::string text, const std::string& prefix) {
    for (std::size_t at; (at = text.find(prefix)) != std::string::npos;)
        text.erase(at, prefix.size());
    return text;
}

double rounded(double v) {
    return std::round(v * 1000.0) / 1000.0;
}

json rowJson(const RowPlan& plan, const CheckResult* result, const std::string& verdict,
             const std::string& message, bool earns) {
    json row;
    if (result) {
        row = checkJson(*result);
    } else {
        CheckResult r = checkResultFor(plan.check.request);
        r.view = plan.check.view;
        r.lesson = plan.check.lesson;
        row = {{"stage", r.stage},
               {"tree", r.tree},
               {"view", r.view},
               {"lesson", r.lesson},
               {"name", checkTestName(r)}};
    }
    row["view"] = plan.check.view;
    row["lesson"] = plan.check.lesson;
    row["verdict"] = verdict;
    row["message"] = message;
    row["max_points"] = rounded(plan.points);
    row["points"] = earns ? rounded(plan.points) : 0.0;
    row["visibility"] = plan.visibility;
    row["extra_view"] = plan.extra;
    return row;
}

}  // namespace

json studentRecord(const Assignment& a, const StudentWork& s, const std::vector<StagePlan>& plan,
                   const std::vector<std::vector<CheckResult>>& results, double seconds) {
    json stages = json::array();
    double total = 0;
    std::size_t k = 0;
    bool anyGraded = false;
    for (const StagePlan& p : plan) {
        json st = {{"stage", p.stage->stage},
                   {"tree", p.stage->tree},
                   {"files", p.stage->files},
                   {"max_points", rounded(p.stage->points)},
                   {"visibility", p.stage->visibility}};
        json rows = json::array();
        double earned = 0;
        if (!p.missingFiles.empty()) {
            std::string msg = "not handed in: expected ";
            for (std::size_t f = 0; f < p.missingFiles.size(); ++f)
                msg += (f ? ", " : "") + p.missingFiles[f];
            for (const RowPlan& r : p.rows)
                rows.push_back(rowJson(r, nullptr, "MISSING", msg, false));
            st["status"] = "MISSING";
            st["message"] = msg;
            st["missing_files"] = p.missingFiles;
        } else {
            anyGraded = true;
            const std::vector<CheckResult>& got = results.at(k++);
            bool complete = got.size() == p.rows.size();
            for (const CheckResult& r : got) complete = complete && !r.error;
            if (complete) {
                int passed = 0;
                for (std::size_t i = 0; i < got.size(); ++i) {
                    bool earns = got[i].judgement.verdict != Verdict::Fail;
                    passed += earns;
                    rows.push_back(rowJson(p.rows[i], &got[i], got[i].verdict(),
                                           got[i].judgement.message, earns));
                    if (earns) earned += p.rows[i].points;
                }
                st["status"] = "graded";
                st["message"] = std::to_string(passed) + " of " + std::to_string(got.size()) +
                                " checks show the lesson";
            } else {  // a shader that does not build (or a worker that died): the stage is 0
                const CheckResult* bad = nullptr;
                for (const CheckResult& r : got)
                    if (r.error && !bad) bad = &r;
                std::string verdict = bad ? bad->verdict() : "ERROR";
                std::string msg =
                    bad ? bad->judgement.message : "the stage's results are incomplete";
                for (std::size_t i = 0; i < p.rows.size(); ++i)
                    rows.push_back(rowJson(p.rows[i], i < got.size() ? &got[i] : nullptr, verdict,
                                           msg, false));
                st["status"] = verdict;
                st["message"] = msg;
            }
        }
        st["points"] = rounded(earned);
        st["rows"] = rows;
        total += earned;
        stages.push_back(st);
    }
    // Messages name the student's files as handed in, not by the private snapshot's path.
    if (!s.overlay.empty())
        for (json& st : stages) {
            for (json* m : {&st["message"]})
                *m = withoutPrefix(m->get<std::string>(), s.overlay + "/");
            for (json& row : st["rows"])
                row["message"] = withoutPrefix(row["message"].get<std::string>(), s.overlay + "/");
        }
    return {{"tool", "shadowlab grade"},
            {"report_version", 1},
            {"assignment", a.name},
            {"student", s.name},
            {"status", anyGraded ? "graded" : "MISSING"},
            {"error", nullptr},
            {"notes", s.notes},
            {"files", s.files},
            {"score", rounded(total)},
            {"max_score", rounded(a.maxPoints())},
            {"seconds", seconds},
            {"stages", stages}};
}

json unreadableRecord(const Assignment& a, const StudentWork& s) {
    json stages = json::array();
    for (const AssignmentStage* st : a.due()) {
        json rows = json::array();
        for (const RowPlan& r : planStage(a, *st, ""))
            rows.push_back(rowJson(r, nullptr, "ERROR", s.error, false));
        stages.push_back({{"stage", st->stage},
                          {"tree", st->tree},
                          {"files", st->files},
                          {"max_points", rounded(st->points)},
                          {"visibility", st->visibility},
                          {"status", "ERROR"},
                          {"message", s.error},
                          {"points", 0.0},
                          {"rows", rows}});
    }
    return {{"tool", "shadowlab grade"},
            {"report_version", 1},
            {"assignment", a.name},
            {"student", s.name},
            {"status", "ERROR"},
            {"error", s.error},
            {"notes", s.notes},
            {"files", json::array()},
            {"score", 0.0},
            {"max_score", rounded(a.maxPoints())},
            {"seconds", 0.0},
            {"stages", stages}};
}

namespace {

std::string rowOutput(const json& row) {
    std::ostringstream out;
    out << row.value("verdict", "") << ": " << row.value("message", "") << "\n";
    if (row.contains("expectation") && row["expectation"].is_object())
        out << "expected: " << row["expectation"].value("outcome", "") << "\n";
    if (row.contains("figures") && row["figures"].is_object()) {
        const json& f = row["figures"];
        for (const char* k : {"false_shadow_pct", "false_lit_pct", "edge_p95_px", "mirror_id_pct"})
            if (f.contains(k) && f[k].is_number()) out << k << " " << f[k].get<double>() << "\n";
    }
    if (row.contains("diff") && row["diff"].is_string())
        out << "diff image: "
            << row["diff"].get<std::string>().substr(
                   row["diff"].get<std::string>().find_last_of('/') + 1)
            << " (red: false shadow, blue: false lit, grey: agreement)\n";
    return out.str();
}

}  // namespace

json gradescopeResults(const json& record) {
    json tests = json::array();
    int number = 0;
    for (const json& st : record["stages"]) {
        ++number;
        int sub = 0;
        for (const json& row : st["rows"]) {
            std::string name =
                st["stage"].get<std::string>() + "/" + st["tree"].get<std::string>() + " " +
                row.value("view", "") +
                (row.value("lesson", "").empty() ? "" : " [" + row.value("lesson", "") + "]");
            double pts = row.value("points", 0.0), maxPts = row.value("max_points", 0.0);
            tests.push_back({{"name", name},
                             {"number", std::to_string(number) + "." + std::to_string(++sub)},
                             {"score", pts},
                             {"max_score", maxPts},
                             {"status", pts >= maxPts ? "passed" : "failed"},
                             {"visibility", row.value("visibility", "visible")},
                             {"output", rowOutput(row)},
                             {"tags", {st["stage"], row.value("verdict", "")}},
                             {"extra_data",
                              {{"verdict", row.value("verdict", "")},
                               {"stage_status", st.value("status", "")}}}});
        }
    }
    std::ostringstream out;
    for (const json& n : record["notes"]) out << "note: " << n.get<std::string>() << "\n";
    if (record["error"].is_string()) out << record["error"].get<std::string>() << "\n";
    for (const json& st : record["stages"])
        out << st["stage"].get<std::string>() << "/" << st["tree"].get<std::string>() << ": "
            << st["status"].get<std::string>() << ", " << st["points"].get<double>() << " of "
            << st["max_points"].get<double>() << " points: " << st.value("message", "") << "\n";
    return {{"score", record["score"]},
            {"max_score", record["max_score"]},
            {"execution_time", record.value("seconds", 0.0)},
            {"output", out.str()},
            {"visibility", "visible"},
            {"stdout_visibility", "hidden"},
            {"tests", tests}};
}

std::string recordJunit(const json& record) {
    std::ostringstream out;
    int tests = 0, failures = 0, errors = 0;
    std::ostringstream cases;
    for (const json& st : record["stages"])
        for (const json& row : st["rows"]) {
            ++tests;
            std::string verdict = row.value("verdict", "");
            cases << "    <testcase classname=\""
                  << xmlEscaped(st["stage"].get<std::string>() + "/" +
                                st["tree"].get<std::string>())
                  << "\" name=\""
                  << xmlEscaped(row.value("view", "") + " " + row.value("lesson", ""))
                  << "\">\n      <properties>\n        <property name=\"points\" value=\""
                  << row.value("points", 0.0)
                  << "\"/>\n        <property name=\"max_points\" value=\""
                  << row.value("max_points", 0.0)
                  << "\"/>\n        <property name=\"visibility\" value=\""
                  << xmlEscaped(row.value("visibility", "")) << "\"/>\n      </properties>\n";
            std::string msg = xmlEscaped(row.value("message", ""));
            if (verdict == "FAIL" || verdict == "MISSING") {
                ++failures;
                cases << "      <failure type=\"" << verdict << "\" message=\"" << msg << "\"/>\n";
            } else if (verdict != "PASS" && verdict != "SKIP") {
                ++errors;
                cases << "      <error type=\"" << xmlEscaped(verdict) << "\" message=\"" << msg
                      << "\"/>\n";
            }
            cases << "    </testcase>\n";
        }
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites>\n  <testsuite name=\""
        << xmlEscaped(record.value("assignment", "") + ": " + record.value("student", ""))
        << "\" tests=\"" << tests << "\" failures=\"" << failures << "\" errors=\"" << errors
        << "\">\n"
        << cases.str() << "  </testsuite>\n</testsuites>\n";
    return out.str();
}

std::string recordSummary(const json& record) {
    std::ostringstream out;
    char line[512];
    for (const json& st : record["stages"]) {
        std::snprintf(
            line, sizeof line, "%-16s %-8s %7.2f / %-7.2f %s\n",
            (st["stage"].get<std::string>() + "/" + st["tree"].get<std::string>()).c_str(),
            st["status"].get<std::string>().c_str(), st["points"].get<double>(),
            st["max_points"].get<double>(), st.value("message", "").c_str());
        out << line;
    }
    std::snprintf(line, sizeof line, "total: %.2f of %.2f points\n", record["score"].get<double>(),
                  record["max_score"].get<double>());
    out << line;
    return out.str();
}

}  // namespace sl
