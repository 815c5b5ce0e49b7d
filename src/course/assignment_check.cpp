#include "course/assignment_check.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "io/files.h"

namespace sl {

int recordExitCode(const nlohmann::json& record) {
    int code = 0;
    if (record["status"] == "ERROR") return 2;
    for (const auto& st : record["stages"]) {
        std::string s = st["status"];
        // A due stage MISSING is bad input, as in `check` (GUIDE section 3): exit 2.
        if (s != "graded") return 2;
        for (const auto& row : st["rows"])
            if (row["verdict"] == "FAIL") code = 1;
    }
    return code;
}

namespace {

void writeOrThrow(const std::string& option, const std::string& path, const std::string& text) {
    std::string err = outputPathProblem(path);
    if (err.empty()) err = writeFileAtomically(path, text.data(), text.size());
    if (!err.empty()) throw UsageError(option + ": " + err);
}

}  // namespace

int runAssignmentCheck(const AssignmentCheckArgs& args) {
    if (args.shaders.empty())
        throw UsageError(
            "check --assignment: give the student's work with --shaders DIR (a folder or .zip)");
    if (args.format != "json" && args.format != "gradescope")
        throw UsageError("--format: '" + args.format + "' is not one of json, gradescope");
    for (const auto& [option, path] :
         {std::pair<std::string, std::string>{"--report", args.report}, {"--junit", args.junit}})
        if (!path.empty()) {
            std::string err = outputPathProblem(path);
            if (!err.empty()) throw UsageError(option + ": " + err);
        }
    Assignment a = loadAssignment(args.assignment);
    char tmpl[] = "/tmp/shadowlab-intake-XXXXXX";
    if (!::mkdtemp(tmpl)) throw std::runtime_error("cannot create a temporary folder");
    std::string work = tmpl;
    struct Cleanup {
        std::string dir;
        ~Cleanup() {
            std::error_code ec;
            std::filesystem::remove_all(dir, ec);
        }
    } cleanup{work};
    StudentWork s = intakeSubmission(args.shaders, work + "/s");
    for (const auto& n : s.notes) std::cerr << "shadowlab: note: " << printable(n) << "\n";
    if (!s.error.empty()) std::cerr << "shadowlab: " << printable(s.error) << "\n";
    GradeSettings settings = args.settings;
    if (!args.diffDir.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(args.diffDir, ec);
        if (ec) throw UsageError("--diff-dir: cannot create " + printableName(args.diffDir));
        settings.imageDir = [dir = args.diffDir](const StudentWork&) { return dir; };
    }
    std::cout << "check by " << printableName(args.assignment) << " (" << a.name << "), shaders "
              << printableName(args.shaders) << "\n";
    nlohmann::json record;
    bool platformFailure =
        gradeStudents(a, {s}, settings, [&](std::size_t, const nlohmann::json& r) { record = r; });
    for (const auto& st : record["stages"])
        for (const auto& row : st["rows"]) {
            char line[600];
            std::snprintf(line, sizeof line, "%-44s %-8s %6.2f/%-6.2f %-15s %s\n",
                          (st["stage"].get<std::string>() + "/" + st["tree"].get<std::string>() +
                           "/" + row.value("view", "") + " " + row.value("lesson", ""))
                              .c_str(),
                          row.value("verdict", "").c_str(), row.value("points", 0.0),
                          row.value("max_points", 0.0), row.value("visibility", "").c_str(),
                          printable(row.value("message", "")).substr(0, 300).c_str());
            std::cout << line;
        }
    std::cout << recordSummary(record);
    if (!args.report.empty()) {
        nlohmann::json out = args.format == "gradescope" ? gradescopeResults(record) : record;
        writeOrThrow("--report", args.report,
                     out.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
    }
    if (!args.junit.empty()) writeOrThrow("--junit", args.junit, recordJunit(record));
    return platformFailure ? 3 : recordExitCode(record);
}

}  // namespace sl
