#include "course/intake_adapter.h"

#include <dirent.h>
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>

#include "course/archive.h"
#include "grade/intake.h"
#include "io/files.h"
#include "render/request.h"

namespace sl {

namespace fs = std::filesystem;

namespace {

bool endsWithZip(const std::string& name) {
    if (name.size() < 4) return false;
    std::string ext = name.substr(name.size() - 4);
    std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
    return ext == ".zip";
}

// The one entry of `dir` that is not junk, or "" when there are none or several.
std::string loneEntry(const std::string& dir) {
    std::string only;
    int count = 0;
    if (DIR* d = ::opendir(dir.c_str())) {
        while (dirent* e = ::readdir(d)) {
            std::string n = e->d_name;
            if (n == "." || n == ".." || isJunkName(n)) continue;
            only = n;
            ++count;
        }
        ::closedir(d);
    }
    return count == 1 ? only : "";
}

// A zip handed in inside the submission (Gradescope keeps an uploaded zip as it is), below at
// most three lone wrapper folders: its path, or "".
std::string innerZip(std::string root) {
    for (int level = 0; level < 4; ++level) {
        std::string only = loneEntry(root);
        if (only.empty()) return "";
        std::string path = root + "/" + only;
        struct stat st;
        if (::lstat(path.c_str(), &st) != 0) return "";
        if (S_ISREG(st.st_mode) && endsWithZip(only)) return path;
        if (!S_ISDIR(st.st_mode)) return "";
        root = path;
    }
    return "";
}

// `text` with every instructor's path in `paths` (longest first) replaced by what the student
// calls it: the hand-in's own name.
std::string withStudentNames(std::string text,
                             const std::vector<std::pair<std::string, std::string>>& paths) {
    for (const auto& [path, shown] : paths)
        for (std::size_t at;
             path.find('/') != std::string::npos && (at = text.find(path)) != std::string::npos;)
            text.replace(at, path.size(), shown);
    return text;
}

// Notes and error of `s` without the instructor's paths: the hand-in at `path` as the student
// named it, its unpacked copies under `workDir` as the zip's name.
void hideInstructorPaths(StudentWork& s, const std::string& path, const std::string& workDir) {
    std::string handIn = path;
    while (handIn.size() > 1 && handIn.back() == '/') handIn.pop_back();
    handIn = handIn.substr(handIn.find_last_of('/') + 1);
    std::vector<std::pair<std::string, std::string>> paths = {
        {printableName(workDir + "/unpacked-inner"), handIn},
        {workDir + "/unpacked-inner", handIn},
        {printableName(workDir + "/unpacked"), handIn},
        {workDir + "/unpacked", handIn},
        {printableName(workDir), handIn},
        {workDir, handIn},
        {printableName(path), handIn},
        {path, handIn}};
    for (std::string& n : s.notes) n = withStudentNames(n, paths);
    s.error = withStudentNames(s.error, paths);
}

}  // namespace

std::string submissionName(const std::string& path) {
    std::string p = path;
    while (p.size() > 1 && p.back() == '/') p.pop_back();
    std::string base = p.substr(p.find_last_of('/') + 1);
    if (endsWithZip(base)) base.resize(base.size() - 4);
    return base;
}

namespace {

StudentWork intakeInto(const std::string& path, const std::string& workDir,
                       const std::vector<std::string>& stages) {
    StudentWork s;
    s.name = submissionName(path);
    std::error_code ec;
    fs::remove_all(workDir, ec);
    fs::create_directories(workDir, ec);
    struct stat st;
    if (::stat(path.c_str(), &st) != 0) {
        s.error = printableName(path) + ": no such file or folder";
        return s;
    }
    std::string root;
    if (S_ISREG(st.st_mode) && endsWithZip(path)) {
        std::string err = unpackZip(path, workDir + "/unpacked");
        if (!err.empty()) {
            s.error = printableName(s.name) + ".zip refused: " + err;
            return s;
        }
        root = workDir + "/unpacked";
    } else if (S_ISDIR(st.st_mode)) {
        root = path;
    } else {
        s.error = printableName(path) + ": neither a folder nor a .zip";
        return s;
    }
    if (std::string zip = innerZip(root); !zip.empty()) {
        std::string err = unpackZip(zip, workDir + "/unpacked-inner");
        if (!err.empty()) {
            s.error = printableName(fs::path(zip).filename().string()) + " refused: " + err;
            return s;
        }
        s.notes.push_back("unpacked '" + printableName(fs::path(zip).filename().string()) + "'");
        root = workDir + "/unpacked-inner";
    }
    std::string snapshot = workDir + "/snapshot";
    fs::create_directories(snapshot, ec);
    fs::permissions(snapshot, fs::perms::owner_all, ec);
    s.overlay = snapshot;
    try {
        Submission sub = takeSubmission(root, snapshot, shippedTrees().both, stages);
        s.files = sub.files;
        s.notes.insert(s.notes.end(), sub.notes.begin(), sub.notes.end());
    } catch (const NothingHandedIn& e) {
        s.notes.push_back(e.what());  // every due stage MISSING, 0 points
    } catch (const IntakeError& e) {
        s.error = e.what();  // too many, too large, unreadable: the submission is an ERROR
        s.overlay.clear();
    }
    return s;
}

}  // namespace

StudentWork intakeSubmission(const std::string& path, const std::string& workDir,
                             const std::vector<std::string>& stages) {
    StudentWork s = intakeInto(path, workDir, stages);
    hideInstructorPaths(s, path, workDir);
    return s;
}

}  // namespace sl
