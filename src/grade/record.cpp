#include "grade/record.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "grade/bounds.h"
#include "grade/stage_runs.h"
#include "io/json_fields.h"
#include "stages/request.h"

namespace sl {

using nlohmann::json;

namespace {

double rounded(double v) {
    return std::round(v * 1000.0) / 1000.0;
}

std::string withoutPrefix(std::string text, const std::string& prefix) {
    if (prefix.empty()) return text;
    for (std::size_t at; (at = text.find(prefix)) != std::string::npos;)
        text.erase(at, prefix.size());
    return text;
}

// A planned row that was not rendered, with the status and message it gets.
RowRecord unrenderedRow(const RowPlan& plan, Status status, const std::string& message) {
    RowRecord row;
    row.result = unrenderedResult(plan.check.request);
    row.result.view = plan.check.view;
    row.result.lesson = plan.check.lesson;
    row.result.status = status;
    row.result.message = message;
    return row;
}

// Points: a scored row's possible points are its plan's, earned when its status earns them;
// a NOT GRADED row is no score at all.
void score(RowRecord& row, const RowPlan& plan) {
    row.visibility = plan.visibility;
    row.extraView = plan.extra;
    row.result.view = plan.check.view;
    if (!plan.check.lesson.empty()) row.result.lesson = plan.check.lesson;
    row.maxPoints = isScored(row.status()) ? plan.points : 0.0;
    row.points = earnsPoints(row.status()) ? row.maxPoints : 0.0;
}

void sumStage(StageRecord& st) {
    st.points = st.maxPoints = 0;
    st.status = Status::Pass;
    for (const RowRecord& row : st.rows) {
        st.points += row.points;
        st.maxPoints += row.maxPoints;
        st.status = worst(st.status, row.status());
    }
    st.points = rounded(st.points);
    st.maxPoints = rounded(st.maxPoints);
}

StageRecord stageOf(const StagePlan& p) {
    StageRecord st;
    st.stage = p.stage;
    st.tree = p.tree;
    st.visibility = p.visibility;
    st.files = p.files;
    st.missingFiles = p.missingFiles;
    return st;
}

void sumStudent(StudentRecord& r) {
    r.score = r.maxScore = 0;
    for (const StageRecord& st : r.stages) {
        r.score += st.points;
        r.maxScore += st.maxPoints;
    }
    r.score = rounded(r.score);
    r.maxScore = rounded(r.maxScore);
}

}  // namespace

double StudentRecord::adjusted() const {
    double t = 0;
    for (const Adjustment& a : adjustments) t += a.points;
    return t;
}

double StudentRecord::total() const {
    const double t = score - (late ? late->penalty : 0.0) + adjusted();
    return rounded(std::clamp(t, 0.0, std::max(maxScore, 0.0)));
}

Status StudentRecord::status() const {
    Status s = Status::Pass;
    for (const StageRecord& st : stages) s = worst(s, st.status);
    return s;
}

StageRecord stageRecord(const StagePlan& p, const std::vector<CheckResult>* got,
                        const std::string& overlay) {
    StageRecord st = stageOf(p);
    if (p.missing()) {
        std::string msg = "not handed in: expected " + commaList(p.missingFiles);
        for (const RowPlan& row : p.rows) {
            st.rows.push_back(unrenderedRow(row, Status::Missing, msg));
            score(st.rows.back(), row);
        }
        st.message = msg;
    } else if (!p.skipped.empty()) {
        for (const RowPlan& row : p.rows) {
            st.rows.push_back(unrenderedRow(row, Status::Skip, p.skipped));
            score(st.rows.back(), row);
        }
        st.message = p.skipped;
    } else if (p.rows.empty()) {  // nothing to render, nothing to earn
        st.message = "no checks planned";
    } else {
        static const std::vector<CheckResult> none;
        const std::vector<CheckResult>& results = got ? *got : none;
        const CheckResult* bad = nullptr;  // the row that stopped the stage's job
        for (const CheckResult& r : results)
            if (unjudged(r.status) && !bad) bad = &r;
        CheckResult incomplete;
        if (!bad && results.size() != p.rows.size()) {
            incomplete.status = Status::NotGraded;
            incomplete.message = "the stage's results are incomplete (a platform problem)";
            bad = &incomplete;
        }
        for (std::size_t i = 0; i < p.rows.size(); ++i) {
            RowRecord row;
            if (!bad) {
                row.result = results[i];
            } else {
                // Every row takes the failure of the row that stopped the job; the others carry
                // it cut short (the stage's message has it whole): outputs stay small.
                const bool own = i < results.size() && &results[i] == bad;
                const std::string message =
                    own ? bad->message : capped(bad->message, kMaxInheritedMessage);
                row = i < results.size() ? RowRecord{results[i]}
                                         : unrenderedRow(p.rows[i], bad->status, message);
                row.result.status = bad->status;
                row.result.message = message;
            }
            score(row, p.rows[i]);
            st.rows.push_back(std::move(row));
        }
        if (bad) {
            st.message = bad->message;
        } else {
            // A student reads it: their rows only (a hidden stage is the instructor's: all).
            int shown = 0, counted = 0;
            for (const RowRecord& row : st.rows) {
                if (st.visibility != "hidden" && !seenByStudent(st, row)) continue;
                ++counted;
                shown += earnsPoints(row.status());
            }
            st.message = std::to_string(shown) + " of " + std::to_string(counted) +
                         (counted < int(st.rows.size()) ? " visible" : "") +
                         " checks show the lesson";
        }
    }
    sumStage(st);
    // Messages and source notes name the student's files as handed in, not by the private
    // snapshot's path (grades/work/NAME/snapshot/margin/lit.frag:33 is margin/lit.frag:33), and
    // our shipped files by their tree (shaders_core/common/phong.glsl): no grader's folder
    // reaches a record, a page or a report.
    const std::string snapshot = overlay.empty() ? "" : overlay + "/";
    auto replaceAll = [](std::string text, const std::string& from, const std::string& to) {
        for (std::size_t at = 0; !from.empty() && (at = text.find(from, at)) != std::string::npos;
             at += to.size())
            text.replace(at, from.size(), to);
        return text;
    };
    auto shown = [&](std::string text) {
        text = withoutPrefix(std::move(text), snapshot);
        // The folder itself ("allowed: files under DIR and ..."), then our trees by their name.
        if (!overlay.empty()) text = replaceAll(std::move(text), overlay, "your hand-in");
        for (GlslTree t : {GlslTree::Core, GlslTree::Legacy}) {
            const std::string root = shaderTreeRoot(t);
            text = replaceAll(std::move(text), root, root.substr(root.rfind('/') + 1));
        }
        return text;
    };
    st.message = shown(st.message);
    for (RowRecord& row : st.rows) {
        row.result.message = shown(row.result.message);
        for (std::string& note : row.result.sourceNotes) note = shown(std::move(note));
    }
    return st;
}

bool seenByStudent(const StageRecord& st, const RowRecord& row) {
    return st.visibility != "hidden" && row.visibility != "hidden";
}

// A kept record holds each row's points to 3 decimals and the stage's sum exactly (19 rows of
// 20/19 add up to 20.007): the seen points are taken from the fewer rounded rows, the stage's
// less its hidden rows or the seen rows added up, so a stage without hidden rows shows the
// points grades.csv and the class page show.
bool hidesPoints(const StudentRecord& record) {
    for (const StageRecord& st : record.stages) {
        if (st.visibility == "hidden" && st.maxPoints > 0) return true;
        for (const RowRecord& row : st.rows)
            if (!seenByStudent(st, row) && row.maxPoints > 0) return true;
    }
    return false;
}

SeenStage seenStage(const StageRecord& st) {
    SeenStage out;
    double hiddenPoints = 0, hiddenMax = 0;
    for (const RowRecord& row : st.rows) {
        if (!seenByStudent(st, row)) {
            ++out.hidden;
            hiddenPoints += row.points;
            hiddenMax += row.maxPoints;
            continue;
        }
        ++out.seen;
        out.shown += earnsPoints(row.status());
        out.points += row.points;
        out.maxPoints += row.maxPoints;
        out.status = worst(out.status, row.status());
    }
    if (out.seen > 0 && out.hidden < out.seen) {
        out.points = std::max(0.0, st.points - hiddenPoints);
        out.maxPoints = std::max(0.0, st.maxPoints - hiddenMax);
    }
    return out;
}

StudentRecord buildRecord(const GradingPlan& plan, const StudentWork& s,
                          const std::vector<StageRecord>& stages, double seconds) {
    StudentRecord out;
    out.assignment = plan.name;
    out.student = s.name;
    out.notes = s.notes;
    out.files = s.files;
    out.seconds = seconds;
    out.handInHash = s.hash;
    out.stages = stages;
    for (const StageRecord& st : stages)
        for (const RowRecord& row : st.rows)
            if (out.backend.empty() && !row.result.backend.empty()) {
                out.backend = row.result.backend;
                out.machine = row.result.machine;
            }
    sumStudent(out);
    return out;
}

StudentRecord unreadableRecord(const GradingPlan& plan, const StudentWork& s) {
    StudentRecord out;
    out.assignment = plan.name;
    out.student = s.name;
    out.error = s.error;
    out.notes = s.notes;
    out.handInHash = s.hash;
    for (const StagePlan& p : plan.stages) {
        StageRecord st = stageOf(p);
        st.missingFiles.clear();
        for (const RowPlan& row : p.rows) {
            st.rows.push_back(
                unrenderedRow(row, s.platformFailure ? Status::NotGraded : Status::Error, s.error));
            score(st.rows.back(), row);
        }
        st.message = s.error;
        sumStage(st);
        out.stages.push_back(std::move(st));
    }
    sumStudent(out);
    return out;
}

RowCounts countRows(const StudentRecord& r) {
    RowCounts c;
    for (const StageRecord& st : r.stages)
        for (const RowRecord& row : st.rows) {
            ++c.total;
            switch (row.status()) {
                case Status::Pass:
                    ++c.passed;
                    break;
                case Status::Skip:
                    ++c.skipped;
                    break;
                case Status::Fail:
                    ++c.failed;
                    break;
                case Status::Missing:
                    ++c.missing;
                    break;
                case Status::NotGraded:
                    ++c.notGraded;
                    break;
                default:
                    ++c.errors;
            }
        }
    return c;
}

// A name that is not UTF-8 (a hand-in folder named by an old zip tool in Latin-1) is kept in
// the record as its bytes in hex beside its escaped text: JSON holds text only, and a record must
// be found again under the exact name its hand-in has (or it is "no record" on every run).
static std::string hexOf(const std::string& bytes) {
    static const char* digits = "0123456789abcdef";
    std::string out;
    for (unsigned char c : bytes) {
        out += digits[c >> 4];
        out += digits[c & 15];
    }
    return out;
}

static std::string bytesOf(const std::string& hex) {
    auto value = [](char c) {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        throw std::invalid_argument("student_bytes: not lower-case hex");
    };
    if (hex.size() % 2) throw std::invalid_argument("student_bytes: an odd number of digits");
    std::string out;
    for (std::size_t i = 0; i < hex.size(); i += 2)
        out += char(value(hex[i]) * 16 + value(hex[i + 1]));
    return out;
}

static json adjustmentsJson(const std::vector<Adjustment>& adjustments) {
    json out = json::array();
    for (const Adjustment& a : adjustments)
        out.push_back({{"stage", a.stage}, {"points", a.points}, {"reason", a.reason}});
    return out;
}

static json ownCheckJson(const std::optional<OwnCheck>& o) {
    if (!o) return json();
    json rows = json::array();
    for (const OwnCheckRow& d : o->disagreements)
        rows.push_back({{"stage", d.stage},
                        {"tree", d.tree},
                        {"row", d.row},
                        {"home", statusName(d.home)},
                        {"grade", statusName(d.grade)},
                        {"seen", d.seen}});
    return {{"file", o->file},
            {"problem", o->problem.empty() ? json() : json(o->problem)},
            {"machine", {{"backend", o->backend}, {"renderer", o->machine}}},
            {"compared", o->compared},
            {"agreed", o->agreed},
            {"seen_compared", o->seenCompared},
            {"seen_agreed", o->seenAgreed},
            {"not_comparable", o->notComparable},
            {"unmatched", o->unmatched},
            {"disagreed", o->disagreed},
            {"disagreements", rows}};
}

static OwnCheck ownCheckFromJson(const json& j) {
    auto status = [](const json& name) {
        std::optional<Status> s = statusFromName(name.get<std::string>());
        if (!s) throw std::invalid_argument("own_check: a status is unknown");
        return *s;
    };
    OwnCheck o;
    o.file = j.at("file").get<std::string>();
    if (j.at("problem").is_string()) o.problem = j["problem"].get<std::string>();
    o.backend = j.at("machine").at("backend").get<std::string>();
    o.machine = j.at("machine").at("renderer").get<std::string>();
    o.compared = j.at("compared").get<int>();
    o.agreed = j.at("agreed").get<int>();
    o.seenCompared = j.at("seen_compared").get<int>();
    o.seenAgreed = j.at("seen_agreed").get<int>();
    o.notComparable = j.at("not_comparable").get<int>();
    o.unmatched = j.at("unmatched").get<int>();
    o.disagreed = j.at("disagreed").get<int>();
    for (const json& d : j.at("disagreements"))
        o.disagreements.push_back({d.at("stage").get<std::string>(),
                                   d.at("tree").get<std::string>(), d.at("row").get<std::string>(),
                                   status(d.at("home")), status(d.at("grade")),
                                   d.at("seen").get<bool>()});
    return o;
}

json recordJson(const StudentRecord& r) {
    json stages = json::array();
    for (const StageRecord& st : r.stages) {
        json rows = json::array();
        for (const RowRecord& row : st.rows) {
            json j = checkJson(row.result);
            j["points"] = rounded(row.points);
            j["max_points"] = rounded(row.maxPoints);
            j["visibility"] = row.visibility;
            j["extra_view"] = row.extraView;
            rows.push_back(std::move(j));
        }
        stages.push_back({{"stage", st.stage},
                          {"tree", st.tree},
                          {"files", st.files},
                          {"missing_files", st.missingFiles},
                          {"status", statusName(st.status)},
                          {"message", st.message},
                          {"points", st.points},
                          {"max_points", st.maxPoints},
                          {"visibility", st.visibility},
                          {"rows", rows}});
    }
    RowCounts c = countRows(r);
    json roster;
    if (r.roster)
        roster = {{"id", r.roster->id}, {"name", r.roster->name}, {"email", r.roster->email}};
    return {{"tool", r.tool},
            {"report_format", kReport.name},
            {"report_version", kReport.version},
            {"assignment", r.assignment},
            {"student", validUtf8(r.student) == r.student ? r.student : escapedName(r.student)},
            {"student_bytes", validUtf8(r.student) == r.student ? json() : json(hexOf(r.student))},
            {"status", statusName(r.status())},
            {"exit_code", r.exitCode()},
            {"error", r.error.empty() ? json() : json(r.error)},
            {"notes", r.notes},
            {"files", r.files},
            {"score", r.score},
            {"max_score", r.maxScore},
            {"seconds", r.seconds},
            {"seed", r.seed ? json(*r.seed) : json()},
            {"machine", {{"backend", r.backend}, {"renderer", r.machine}}},
            {"hashes", {{"hand_in", r.handInHash}, {"assignment", r.assignmentHash}}},
            {"roster", roster},
            {"flags", r.flags},
            {"adjustments", adjustmentsJson(r.adjustments)},
            {"own_check", ownCheckJson(r.ownCheck)},
            {"late", r.late ? json{{"handed_in", r.late->handedIn},
                                   {"source", r.late->source},
                                   {"minutes", rounded(r.late->minutes)},
                                   {"days", r.late->days},
                                   {"penalty", rounded(r.late->penalty)},
                                   {"capped", r.late->capped}}
                            : json()},
            {"summary",
             {{"checked", c.total},
              {"passed", c.passed},
              {"failed", c.failed},
              {"skipped", c.skipped},
              {"missing", c.missing},
              {"errors", c.errors},
              {"not_graded", c.notGraded},
              {"exit_code", r.exitCode()},
              {"seconds", r.seconds}}},
            {"stages", stages}};
}

json keptRecordJson(const StudentRecord& r) {
    json j = recordJson(r);
    j["record_format"] = kKeptRecord.name;
    j["record_version"] = kKeptRecord.version;
    return j;
}

namespace {

// The record's fields, as the report and the kept record both hold them.
StudentRecord recordFields(const json& j) {
    try {
        StudentRecord r;
        r.tool = j.at("tool").get<std::string>();
        r.assignment = j.at("assignment").get<std::string>();
        r.student = j.at("student").get<std::string>();
        if (j.contains("student_bytes") && j["student_bytes"].is_string())
            r.student = bytesOf(j["student_bytes"].get<std::string>());
        if (j.at("error").is_string()) r.error = j["error"].get<std::string>();
        r.notes = j.at("notes").get<std::vector<std::string>>();
        r.files = j.at("files").get<std::vector<std::string>>();
        r.seconds = j.at("seconds").get<double>();
        if (!j.at("seed").is_null()) r.seed = j["seed"].get<std::uint64_t>();
        r.backend = j.at("machine").at("backend").get<std::string>();
        r.machine = j.at("machine").at("renderer").get<std::string>();
        r.handInHash = j.at("hashes").at("hand_in").get<std::string>();
        r.assignmentHash = j.at("hashes").at("assignment").get<std::string>();
        if (j.contains("flags")) r.flags = j["flags"].get<std::vector<std::string>>();
        if (j.contains("adjustments"))
            for (const json& a : j["adjustments"])
                r.adjustments.push_back({a.at("stage").get<std::string>(),
                                         a.at("points").get<double>(),
                                         a.at("reason").get<std::string>()});
        if (j.contains("late") && !j["late"].is_null()) {
            const json& l = j["late"];
            r.late =
                LateRecord{l.at("handed_in").get<std::string>(), l.at("source").get<std::string>(),
                           l.at("minutes").get<double>(),        l.at("days").get<int>(),
                           l.at("penalty").get<double>(),        l.value("capped", false)};
        }
        if (j.contains("own_check") && !j["own_check"].is_null())
            r.ownCheck = ownCheckFromJson(j["own_check"]);
        if (j.contains("roster") && !j["roster"].is_null())
            r.roster = RosterInfo{j["roster"].at("id").get<std::string>(),
                                  j["roster"].at("name").get<std::string>(),
                                  j["roster"].at("email").get<std::string>()};
        for (const json& s : j.at("stages")) {
            StageRecord st;
            st.stage = s.at("stage").get<std::string>();
            st.tree = s.at("tree").get<std::string>();
            st.files = s.at("files").get<std::vector<std::string>>();
            st.missingFiles = s.at("missing_files").get<std::vector<std::string>>();
            std::optional<Status> status = statusFromName(s.at("status").get<std::string>());
            if (!status) throw std::invalid_argument("a stage's status is unknown");
            st.status = *status;
            st.message = s.at("message").get<std::string>();
            st.points = s.at("points").get<double>();
            st.maxPoints = s.at("max_points").get<double>();
            st.visibility = s.at("visibility").get<std::string>();
            for (const json& row : s.at("rows")) {
                RowRecord rr;
                rr.result = checkResultFromJson(row);
                rr.points = row.at("points").get<double>();
                rr.maxPoints = row.at("max_points").get<double>();
                rr.visibility = row.at("visibility").get<std::string>();
                rr.extraView = row.at("extra_view").get<bool>();
                st.rows.push_back(std::move(rr));
            }
            r.stages.push_back(std::move(st));
        }
        r.score = j.at("score").get<double>();
        r.maxScore = j.at("max_score").get<double>();
        return r;
    } catch (const json::exception& e) {
        throw std::invalid_argument(std::string("a student record: ") + e.what());
    }
}

}  // namespace

StudentRecord recordFromJson(const json& j) {
    requireFormat(j, kKeptRecord, "record_format", "record_version", "a kept record");
    return recordFields(j);
}

StudentRecord reportFromJson(const json& j) {
    requireFormat(j, kReport, "report_format", "report_version", "a check report");
    return recordFields(j);
}

}  // namespace sl
