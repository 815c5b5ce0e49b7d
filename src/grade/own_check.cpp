#include "grade/own_check.h"

#include <map>
#include <set>
#include <stdexcept>
#include <tuple>

#include "grade/formats.h"
#include "grade/reports.h"
#include "io/files.h"

namespace sl {

using nlohmann::json;

namespace {

constexpr std::size_t kMaxProblemText = 160;
constexpr int kMaxJsonDepth = 64;  // a record nests 5 deep; a deeper file is no report

using RowKey = std::tuple<std::string, std::string, std::string, std::string>;

RowKey keyOf(const CheckResult& r) {
    return {r.stage, r.tree, r.view, r.lesson};
}

// The report's JSON, or why it is not a check report (a short line, the student's text capped).
std::string parseReport(const std::string& text, StudentRecord& out) {
    bool tooDeep = false;
    json j = json::parse(
        text,
        [&](int depth, json::parse_event_t, json&) {
            tooDeep = tooDeep || depth > kMaxJsonDepth;
            return !tooDeep;
        },
        false);
    if (tooDeep) return "not a check report (nested deeper than any report)";
    if (j.is_discarded()) return "not JSON";
    if (!j.is_object()) return "not a check report (not a JSON object)";
    const json tool = j.value("tool", json());
    if (!tool.is_string() || tool.get<std::string>().rfind("shadowlab check", 0) != 0)
        return "not a shadowlab check report (tool: " +
               capped(printable(tool.is_string() ? tool.get<std::string>() : tool.dump()), 60) +
               ")";
    const json version = j.value("report_version", json());
    if (version != json(kReport.version))
        return "report_version " + capped(printable(version.dump()), 20) +
               "; this grader reads version " + std::to_string(kReport.version) +
               " (check it again with this release)";
    try {
        out = reportFromJson(j);
    } catch (const std::exception& e) {
        return "not a check report this grader reads (" +
               capped(printable(e.what()), kMaxProblemText) + ")";
    }
    return "";
}

struct GradeRow {
    const StageRecord* stage;
    const RowRecord* row;
};

void compareRow(OwnCheck& o, const RowRecord& home, const GradeRow& g) {
    const CheckResult& ours = g.row->result;
    if (ours.seed != home.result.seed || ours.status == Status::NotGraded ||
        home.status() == Status::NotGraded) {
        ++o.notComparable;
        return;
    }
    const bool seen = seenByStudent(*g.stage, *g.row);
    const bool agree = home.status() == ours.status;
    ++o.compared;
    o.agreed += agree;
    o.seenCompared += seen;
    o.seenAgreed += seen && agree;
    if (agree) return;
    ++o.disagreed;
    if (o.disagreements.size() < kMaxOwnCheckRows)
        o.disagreements.push_back(
            {g.stage->stage, g.stage->tree, rowName(*g.row), home.status(), ours.status, seen});
}

}  // namespace

OwnCheck compareOwnCheck(const HandInFile& report, const StudentRecord& grade) {
    OwnCheck o;
    o.file = report.name;
    o.problem = report.problem;
    StudentRecord home;
    if (o.problem.empty()) o.problem = parseReport(report.text, home);
    if (!o.problem.empty()) return o;
    o.backend = capped(printable(home.backend), 80);
    o.machine = capped(printable(home.machine), 200);
    std::map<RowKey, GradeRow> rows;
    for (const StageRecord& st : grade.stages)
        for (const RowRecord& row : st.rows) rows.emplace(keyOf(row.result), GradeRow{&st, &row});
    std::set<RowKey> used;  // a row given twice in the report counts once
    for (const StageRecord& st : home.stages)
        for (const RowRecord& row : st.rows) {
            auto it = rows.find(keyOf(row.result));
            if (it == rows.end() || !used.insert(it->first).second) {
                ++o.unmatched;
                continue;
            }
            compareRow(o, row, it->second);
        }
    if (o.compared == 0 && o.notComparable == 0)
        o.problem =
            "none of its " + std::to_string(o.unmatched) + " rows is a row this assignment grades";
    else if (o.compared == 0)  // nothing to agree on: said, not counted as agreeing
        o.problem = "none of its rows could be compared (" + std::to_string(o.notComparable) +
                    " at another displaced-view seed than the grade's, or not graded)";
    return o;
}

std::vector<std::string> ownCheckNotes(const OwnCheck& o) {
    const std::string head = "`" + printableName(o.file) + "` (your own check report) ";
    if (!o.problem.empty()) return {head + "was not compared with the grade: " + o.problem};
    std::vector<std::string> out;
    if (o.unmatched > 0)
        out.push_back(head + "has " + std::to_string(o.unmatched) +
                      (o.unmatched == 1 ? " row" : " rows") +
                      " this assignment does not grade: not compared");
    if (o.notComparable > 0)
        out.push_back(head + "has " + std::to_string(o.notComparable) +
                      (o.notComparable == 1 ? " row" : " rows") +
                      " not compared: another displaced-view seed than the grade's, or not "
                      "graded on one side");
    return out;
}

void attachOwnCheck(StudentRecord& record, const HandInFile& report) {
    record.ownCheck = compareOwnCheck(report, record);
    for (const std::string& n : ownCheckNotes(*record.ownCheck)) record.notes.push_back(n);
}

}  // namespace sl
