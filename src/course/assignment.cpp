#include "course/assignment.h"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <set>
#include <sstream>

#include "course/json_lines.h"
#include "gradebook/late_policy.h"
#include "io/files.h"
#include "io/json_fields.h"
#include "scene/scene_json.h"
#include "stages/drawn.h"
#include "stages/expectations.h"
#include "stages/registry.h"
#include "stages/stage.h"

namespace sl {

using nlohmann::json;

const std::vector<std::string>& visibilityNames() {
    static const std::vector<std::string> names = {"visible", "hidden", "after_due_date",
                                                   "after_published"};
    return names;
}

namespace {

constexpr std::size_t kMaxAssignmentBytes = 1u << 20;

// "FILE: /json/path (line N)": the value's line, or its nearest parent's (a missing field).
std::string placeOf(const std::string& origin, const std::map<std::string, int>& lines,
                    const std::string& path) {
    std::string p = path;
    int line = 0;
    while (true) {
        auto it = lines.find(p);
        if (it != lines.end()) {
            line = it->second;
            break;
        }
        if (p.empty()) break;
        p = p.substr(0, p.rfind('/'));
    }
    return origin + ": " + (path.empty() ? "/" : path) +
           (line ? " (line " + std::to_string(line) + ")" : "");
}

class Reader {
  public:
    Reader(std::string origin, const std::map<std::string, int>& lines)
        : origin_(std::move(origin)), lines_(lines) {}

    [[noreturn]] void fail(const std::string& path, const std::string& what) const {
        throw AssignmentError(placeOf(origin_, lines_, path) + ": " + what);
    }

    void allowKeys(const json& obj, const std::string& path, std::set<std::string> keys) const {
        if (!obj.is_object()) fail(path, "must be an object");
        std::string unknown = unknownKey(obj, keys);
        if (!unknown.empty()) fail(path + "/" + unknown, unknownFieldMessage(keys));
    }

    std::string text(const json& v, const std::string& path) const {
        if (!v.is_string()) fail(path, "must be a string, got " + std::string(v.type_name()));
        std::string s = v.get<std::string>();
        if (s.size() > 4096) fail(path, "longer than 4096 characters");
        return s;
    }

    double number(const json& v, const std::string& path, double lo, double hi) const {
        if (!v.is_number()) fail(path, "must be a number, got " + std::string(v.type_name()));
        double d = v.get<double>();
        if (!std::isfinite(d) || d < lo || d > hi) {
            std::ostringstream s;
            s << "must be a number in [" << lo << ", " << hi << "], got " << d;
            fail(path, s.str());
        }
        return d;
    }

    glm::vec3 vec3(const json& v, const std::string& path) const {
        if (!v.is_array() || v.size() != 3) fail(path, "must be an array of 3 numbers");
        return {float(number(v[0], path + "/0", -1e4, 1e4)),
                float(number(v[1], path + "/1", -1e4, 1e4)),
                float(number(v[2], path + "/2", -1e4, 1e4))};
    }

    std::string visibility(const json& v, const std::string& path) const {
        std::string s = text(v, path);
        const auto& names = visibilityNames();
        if (std::find(names.begin(), names.end(), s) == names.end())
            fail(path,
                 "'" + s + "' is not one of visible, hidden, after_due_date, after_published");
        return s;
    }

  private:
    std::string origin_;
    const std::map<std::string, int>& lines_;
};

bool shippedFolder(const std::string& tree, const std::string& stage) {
    struct stat st;
    std::string root = shaderTreeRoot(tree == "legacy" ? GlslTree::Legacy : GlslTree::Core);
    return ::stat((root + "/" + stage).c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

bool shippedFile(const std::string& tree, const std::string& rel) {
    std::string text;
    std::string root = shaderTreeRoot(tree == "legacy" ? GlslTree::Legacy : GlslTree::Core);
    return readRegularFile(root + "/" + rel, 1u << 20, text).empty();
}

// The scenes and view names a stage is graded in (its lessons' scenes).
std::set<std::string> viewNamesOf(const std::string& stage, const std::string& tree,
                                  std::set<std::string>& scenes) {
    std::set<std::string> names;
    for (const Expectation* e : lessonsOf(expectations(), stage, tree)) {
        std::string scene = e->scene.empty() ? defaultSceneOf(stage) : e->scene;
        scenes.insert(scene);
        for (const GradingView& v : gradingViews(scene)) names.insert(v.name);
    }
    // The view displaced by the run's seed (check_run.h, checkCases): in the stage's own scene.
    if (findStage(stage)) names.insert("displaced");
    // The rows whose method parameters the seed draws (stages/drawn.h): the same displaced view.
    if (!drawnRowsOf(stage, tree).empty()) names.insert("drawn");
    return names;
}

LatePolicy readLate(const Reader& in, const json& j) {
    in.allowKeys(j, "/late", {"deadline", "grace_minutes", "penalty_per_day", "cap"});
    LatePolicy p;
    if (!j.contains("deadline")) in.fail("/late/deadline", "missing (ISO 8601 with a zone)");
    p.deadlineText = in.text(j["deadline"], "/late/deadline");
    std::optional<long long> t = parseIsoTime(p.deadlineText);
    if (!t)
        in.fail("/late/deadline",
                "'" + p.deadlineText + "' is not ISO 8601 with a zone (2026-12-04T23:59:00+01:00)");
    p.deadline = *t;
    if (j.contains("grace_minutes"))
        p.graceMinutes = in.number(j["grace_minutes"], "/late/grace_minutes", 0, 525600);
    if (!j.contains("penalty_per_day"))
        in.fail("/late/penalty_per_day", "missing (percent of the points per day late)");
    p.penaltyPerDayPct = in.number(j["penalty_per_day"], "/late/penalty_per_day", 0, 100);
    if (j.contains("cap")) p.capPct = in.number(j["cap"], "/late/cap", 0, 100);
    return p;
}

AssignmentStage readStage(const Reader& in, const json& j, const std::string& path) {
    in.allowKeys(
        j, path,
        {"stage", "tree", "due", "files", "points", "visibility", "lessons", "views", "todo"});
    AssignmentStage s;
    if (!j.contains("stage")) in.fail(path + "/stage", "missing (a stage id is required)");
    s.stage = in.text(j["stage"], path + "/stage");
    const StageInfo* info = findStage(s.stage);
    if (!info) {
        std::string ids;
        for (const auto& id : stageIds()) ids += (ids.empty() ? "" : ", ") + id;
        in.fail(path + "/stage", "unknown stage '" + s.stage + "' (stages: " + ids + ")");
    }
    s.tree = j.contains("tree") ? in.text(j["tree"], path + "/tree") : "core";
    if (s.tree != "core" && s.tree != "legacy")
        in.fail(path + "/tree", "'" + s.tree + "' is not one of core, legacy");
    if (info->legacyOnly && s.tree == "core")
        in.fail(path + "/tree", "stage " + s.stage + " runs in the legacy tree only");
    if (!shippedFolder(s.tree, s.stage))
        in.fail(path + "/stage", "stage " + s.stage + " has no shaders in the " + s.tree +
                                     " tree (its method is fixed-function GL, drawn by the "
                                     "program): there is nothing to hand in, so it cannot be "
                                     "assigned");
    if (j.contains("due")) {
        if (!j["due"].is_boolean()) in.fail(path + "/due", "must be true or false");
        s.due = j["due"].get<bool>();
    }
    if (!j.contains("files")) in.fail(path + "/files", "missing (the files a student hands in)");
    const json& files = j["files"];
    if (!files.is_array() || files.empty() || files.size() > 16)
        in.fail(path + "/files", "must be an array of 1 to 16 file names");
    for (std::size_t k = 0; k < files.size(); ++k) {
        std::string p = path + "/files/" + std::to_string(k);
        std::string f = in.text(files[k], p);
        if (f.rfind(s.stage + "/", 0) != 0 || f.find("..") != std::string::npos ||
            f.find("//") != std::string::npos)
            in.fail(p, "'" + f + "' must be a file of the stage's folder (" + s.stage + "/...)");
        if (!shippedFile(s.tree, f))
            in.fail(p, "'" + f + "' is not a shipped file of the " + s.tree + " tree");
        s.files.push_back(f);
    }
    if (!j.contains("points")) in.fail(path + "/points", "missing (the stage's points)");
    s.points = in.number(j["points"], path + "/points", 0, 1e6);
    if (j.contains("visibility"))
        s.visibility = in.visibility(j["visibility"], path + "/visibility");
    if (j.contains("todo")) s.todo = in.text(j["todo"], path + "/todo");
    std::set<std::string> labels;
    for (const Expectation* e : lessonsOf(expectations(), s.stage, s.tree))
        labels.insert(e->label());
    if (j.contains("lessons")) {
        if (!j["lessons"].is_object()) in.fail(path + "/lessons", "must be an object");
        for (auto it = j["lessons"].begin(); it != j["lessons"].end(); ++it) {
            std::string p = path + "/lessons/" + it.key();
            if (!labels.count(it.key()))
                in.fail(p, "no lesson '" + it.key() + "' for " + s.stage + "/" + s.tree +
                               " (lessons: " + commaList(labels) + ")");
            s.lessons[it.key()] = in.number(*it, p, 0, 1e6);
        }
    }
    std::set<std::string> scenes;
    std::set<std::string> viewNames = viewNamesOf(s.stage, s.tree, scenes);
    if (j.contains("views")) {
        if (!j["views"].is_object()) in.fail(path + "/views", "must be an object");
        for (auto it = j["views"].begin(); it != j["views"].end(); ++it) {
            std::string p = path + "/views/" + it.key();
            if (!viewNames.count(it.key()))
                in.fail(p, "no view '" + it.key() + "' in " + s.stage +
                               "'s scenes (views: " + commaList(viewNames) + ")");
            WeightedView w;
            if (it->is_object()) {
                in.allowKeys(*it, p, {"weight", "visibility"});
                if (it->contains("weight"))
                    w.weight = in.number((*it)["weight"], p + "/weight", 0, 1e6);
                if (it->contains("visibility"))
                    w.visibility = in.visibility((*it)["visibility"], p + "/visibility");
            } else {
                w.weight = in.number(*it, p, 0, 1e6);
            }
            s.views[it.key()] = w;
        }
    }
    return s;
}

ExtraView readExtraView(const Reader& in, const json& j, const std::string& path) {
    in.allowKeys(j, path, {"name", "scene", "eye", "at", "light", "fovy", "weight", "why"});
    ExtraView v;
    if (!j.contains("name")) in.fail(path + "/name", "missing (a name for the view)");
    v.name = in.text(j["name"], path + "/name");
    if (v.name.empty() || v.name.find_first_of("/ \t\n") != std::string::npos)
        in.fail(path + "/name", "must be a non-empty name without spaces or '/'");
    v.scene = j.contains("scene") ? in.text(j["scene"], path + "/scene") : "slides";
    auto scenes = builtInScenes();
    if (std::find(scenes.begin(), scenes.end(), v.scene) == scenes.end())
        in.fail(path + "/scene", "'" + v.scene + "' is not a built-in scene");
    if (j.contains("eye")) v.eye = in.vec3(j["eye"], path + "/eye");
    if (j.contains("at")) v.at = in.vec3(j["at"], path + "/at");
    if (j.contains("light")) v.light = in.vec3(j["light"], path + "/light");
    if (j.contains("fovy")) v.fovy = float(in.number(j["fovy"], path + "/fovy", 1, 170));
    if (j.contains("weight")) v.weight = in.number(j["weight"], path + "/weight", 0, 1e6);
    if (!v.eye && !v.at && !v.light && !v.fovy)
        in.fail(path, "an extra view must set at least one of eye, at, light, fovy");
    return v;
}

// The file name of a student's own check report in a hand-in: a plain .json name at its top
// (beside the stage folders), which the intake sets aside and never grades.
std::string readOwnCheckReport(const Reader& in, const json& j) {
    const std::string name = in.text(j, "/own_check_report");
    const bool plain =
        !name.empty() && name.size() <= 64 && std::all_of(name.begin(), name.end(), [](char c) {
            return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-';
        });
    if (!plain || name[0] == '.' || name.size() < 6 ||
        name.compare(name.size() - 5, 5, ".json") != 0)
        in.fail("/own_check_report",
                "'" + printableName(name) +
                    "' must be a file name ending in .json (letters, digits, '.', '_', '-'; at "
                    "most 64), e.g. check-report.json");
    return name;
}

}  // namespace

std::vector<const AssignmentStage*> Assignment::due() const {
    std::vector<const AssignmentStage*> out;
    for (const auto& s : stages)
        if (s.due) out.push_back(&s);
    return out;
}

double Assignment::maxPoints() const {
    double total = 0;
    for (const auto* s : due()) total += s->points;
    return total;
}

Assignment parseAssignment(const std::string& text, const std::string& origin) {
    json j;
    try {
        j = json::parse(text);
    } catch (const json::parse_error& e) {
        // e.byte is the offset of the fault: its line and column
        std::size_t line = 1, col = 1;
        for (std::size_t k = 0; k + 1 < e.byte && k < text.size(); ++k) {
            col = text[k] == '\n' ? 1 : col + 1;
            line += text[k] == '\n';
        }
        throw AssignmentError(origin + ": line " + std::to_string(line) + ", column " +
                              std::to_string(col) + ": not valid JSON");
    } catch (const json::exception&) {
        // Valid JSON that a double cannot hold (1e400): nlohmann names no position, so the
        // first such number is found again by its text.
        std::map<std::string, std::string> numbers;
        std::map<std::string, int> lines = jsonValueLines(text, &numbers);
        const std::string* first = nullptr;  // in the file's order
        for (const auto& [path, token] : numbers)
            if (!std::isfinite(std::strtod(token.c_str(), nullptr)) &&
                (!first || lines[path] < lines[*first]))
                first = &path;
        if (!first) throw AssignmentError(origin + ": a number out of range");
        throw AssignmentError(placeOf(origin, lines, *first) + ": the number " +
                              numbers[*first].substr(0, 40) + " is out of range");
    }
    Assignment a;
    a.lines = jsonValueLines(text);
    Reader in(origin, a.lines);
    in.allowKeys(
        j, "",
        {"name", "due_date", "stages", "extra_views", "comment", "late", "own_check_report"});
    a.origin = origin;
    if (!j.contains("name")) in.fail("/name", "missing (the assignment's name)");
    a.name = in.text(j["name"], "/name");
    if (j.contains("due_date")) a.dueDate = in.text(j["due_date"], "/due_date");
    if (j.contains("late")) a.late = readLate(in, j["late"]);
    if (j.contains("own_check_report"))
        a.ownCheckReport = readOwnCheckReport(in, j["own_check_report"]);
    if (!j.contains("stages")) in.fail("/stages", "missing (the stages of the assignment)");
    if (!j["stages"].is_array() || j["stages"].empty() || j["stages"].size() > 64)
        in.fail("/stages", "must be an array of 1 to 64 stages");
    std::set<std::string> seen;
    for (std::size_t k = 0; k < j["stages"].size(); ++k) {
        std::string path = "/stages/" + std::to_string(k);
        a.stages.push_back(readStage(in, j["stages"][k], path));
        std::string id = a.stages.back().stage + "/" + a.stages.back().tree;
        if (!seen.insert(id).second) in.fail(path, "stage " + id + " is listed twice");
    }
    if (a.due().empty()) in.fail("/stages", "no stage is due");
    // One hand-in folder per student: two due stages may not claim the same file.
    std::map<std::string, std::string> owners;
    for (std::size_t k = 0; k < a.stages.size(); ++k) {
        if (!a.stages[k].due) continue;
        for (std::size_t f = 0; f < a.stages[k].files.size(); ++f) {
            auto [it, fresh] =
                owners.emplace(a.stages[k].files[f], a.stages[k].stage + "/" + a.stages[k].tree);
            if (!fresh)
                in.fail("/stages/" + std::to_string(k) + "/files/" + std::to_string(f),
                        "'" + it->first + "' is handed in for " + it->second +
                            " already (one folder per student)");
        }
    }
    if (j.contains("extra_views")) {
        if (!j["extra_views"].is_array() || j["extra_views"].size() > 32)
            in.fail("/extra_views", "must be an array of at most 32 views");
        std::set<std::string> names;
        for (std::size_t k = 0; k < j["extra_views"].size(); ++k) {
            std::string path = "/extra_views/" + std::to_string(k);
            a.extraViews.push_back(readExtraView(in, j["extra_views"][k], path));
            const std::string& name = a.extraViews.back().name;
            bool shipped = false;
            for (const GradingView& v : gradingViews(a.extraViews.back().scene))
                shipped = shipped || v.name == name;
            if (!names.insert(name).second || shipped)
                in.fail(path + "/name", "view '" + name + "' is already defined");
        }
    }
    // The students' part: no extra views, no weights of hidden rows (they would say what is
    // graded unseen).
    a.publicJson = {{"name", a.name}, {"due_date", a.dueDate}, {"stages", json::array()}};
    for (const AssignmentStage& s : a.stages) {
        if (!s.due) continue;
        json views = json::object();
        for (const auto& [name, v] : s.views)
            if ((v.visibility.empty() ? s.visibility : v.visibility) != "hidden")
                views[name] = {{"weight", v.weight},
                               {"visibility", v.visibility.empty() ? s.visibility : v.visibility}};
        a.publicJson["stages"].push_back({{"stage", s.stage},
                                          {"tree", s.tree},
                                          {"files", s.files},
                                          {"points", s.points},
                                          {"visibility", s.visibility},
                                          {"lessons", s.lessons},
                                          {"views", views},
                                          {"todo", s.todo}});
    }
    // The student hands the report in by this name: they must read it.
    if (!a.ownCheckReport.empty()) a.publicJson["own_check_report"] = a.ownCheckReport;
    checkAssignmentMeaning(a);
    return a;
}

std::string Assignment::at(const std::string& path) const {
    return placeOf(origin, lines, path);
}

Assignment loadAssignment(const std::string& path) {
    std::string text;
    std::string err = readRegularFile(path, kMaxAssignmentBytes, text);
    if (!err.empty()) throw AssignmentError("--assignment " + printableName(path) + ": " + err);
    return parseAssignment(text, printableName(path));
}

std::vector<RowPlan> planStage(const Assignment& a, const AssignmentStage& s,
                               const std::string& overlay, std::optional<std::uint64_t> seed,
                               int width, int height) {
    RenderRequest base;
    base.stage = s.stage;
    base.tree = s.tree == "legacy" ? GlslTree::Legacy : GlslTree::Core;
    base.overlay = overlay;
    base.width = width;
    base.height = height;
    std::vector<RowPlan> rows;
    std::vector<double> weights;
    std::vector<std::pair<RenderRequest, std::string>> lessons;  // for the extra views
    for (const CheckCase& c : checkCases(base, false, false, seed)) {
        RowPlan row;
        row.check = c;
        auto lw = s.lessons.find(c.lesson);
        auto vw = s.views.find(c.view);
        double w = (lw == s.lessons.end() ? 1.0 : lw->second) *
                   (vw == s.views.end() ? 1.0 : vw->second.weight);
        if (w <= 0) continue;  // a weight of 0 leaves the row out (e.g. a lesson of another file)
        row.visibility = vw == s.views.end() || vw->second.visibility.empty()
                             ? s.visibility
                             : vw->second.visibility;
        rows.push_back(row);
        weights.push_back(w);
        bool known = false;
        for (const auto& l : lessons) known = known || l.second == c.lesson;
        if (!known) lessons.emplace_back(c.request, c.lesson);
    }
    for (const ExtraView& v : a.extraViews)
        for (const auto& [request, label] : lessons) {
            if (effectiveScene(request) != v.scene) continue;
            RowPlan row;
            row.check.request = request;
            RenderRequest& r = row.check.request;
            r.eye = v.eye;
            r.at = v.at;
            r.light = v.light;
            r.fovy = v.fovy;
            row.check.view = v.name;
            row.check.lesson = label;
            row.visibility = "hidden";
            row.extra = true;
            auto lw = s.lessons.find(label);
            double w = (lw == s.lessons.end() ? 1.0 : lw->second) * v.weight;
            if (w <= 0) continue;
            rows.push_back(row);
            weights.push_back(w);
        }
    double total = 0;
    for (double w : weights) total += w;
    for (std::size_t k = 0; k < rows.size(); ++k)
        rows[k].points = total > 0 ? s.points * weights[k] / total : 0;
    return rows;
}

}  // namespace sl
