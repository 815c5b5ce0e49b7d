#include "course/intake_adapter.h"

#include <dirent.h>
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>

#include "course/archive.h"
#include "course/student_grade.h"
#include "grade/intake.h"
#include "io/files.h"

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

// `text` with each private folder of ours named as the student's own file (`shownAs`), longest
// first: a message never names the grader's work folder.
std::string namedAsHandedIn(std::string text,
                            const std::vector<std::pair<std::string, std::string>>& shownAs) {
    for (const auto& [folder, shown] : shownAs)
        for (std::size_t at = 0; (at = text.find(folder, at)) != std::string::npos;) {
            text.replace(at, folder.size(), shown);
            at += shown.size();
        }
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
    for (std::string& n : s.notes) n = namedAsHandedIn(n, paths);
    s.error = namedAsHandedIn(s.error, paths);
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

StudentWork intakeOrThrow(const std::string& path, const std::string& workDir,
                          const std::vector<std::string>& stages,
                          const std::set<std::string>& listed, const std::string& ownReport) {
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
    const std::string handedIn = printableName(fs::path(path).filename().string());
    std::vector<std::pair<std::string, std::string>> shownAs;  // inner zip first: longer path
    UnpackLimits limits;
    limits.asideName = ownReport;  // bounded by the intake's own limit for it, not a shader's
    limits.asideBytes = kMaxSetAsideBytes;
    if (S_ISREG(st.st_mode) && endsWithZip(path)) {
        std::string err = unpackZip(path, workDir + "/unpacked", limits, &s.notes);
        if (!err.empty()) {
            s.error = handedIn + " refused: " + err;
            return s;
        }
        root = workDir + "/unpacked";
        shownAs.emplace_back(root, handedIn);
    } else if (S_ISDIR(st.st_mode)) {
        root = path;
    } else {
        s.error = printableName(path) + ": neither a folder nor a .zip";
        return s;
    }
    if (std::string zip = innerZip(root); !zip.empty()) {
        // The inner zip as the student knows it: inside their own archive or folder.
        std::string inner = handedIn + zip.substr(root.size());
        std::string err = unpackZip(zip, workDir + "/unpacked-inner", limits, &s.notes);
        if (!err.empty()) {
            s.error = printableName(inner) + " refused: " + err;
            return s;
        }
        s.notes.push_back("unpacked '" + printableName(inner) + "'");
        root = workDir + "/unpacked-inner";
        shownAs.insert(shownAs.begin(), {root, printableName(inner)});
    }
    std::string snapshot = workDir + "/snapshot";
    fs::create_directories(snapshot, ec);
    fs::permissions(snapshot, fs::perms::owner_all, ec);
    s.overlay = snapshot;
    try {
        Submission sub =
            takeSubmission(root, snapshot, shippedTrees().both, stages, listed, ownReport);
        s.files = sub.files;
        s.ownReport = std::move(sub.setAside);
        for (const std::string& note : sub.notes) s.notes.push_back(namedAsHandedIn(note, shownAs));
    } catch (const NothingHandedIn& e) {
        s.notes.push_back(namedAsHandedIn(e.what(), shownAs));  // every due stage MISSING
    } catch (const IntakeError& e) {
        // too many, too large, unreadable: the submission is an ERROR
        s.error = namedAsHandedIn(e.what(), shownAs);
        s.overlay.clear();
    }
    return s;
}

}  // namespace

StudentWork intakeSubmission(const std::string& path, const std::string& workDir,
                             const std::vector<std::string>& stages,
                             const std::set<std::string>& listed, const std::string& ownReport) {
    try {
        StudentWork s = intakeOrThrow(path, workDir, stages, listed, ownReport);
        hideInstructorPaths(s, path, workDir);
        return s;
    } catch (const SnapshotWriteError& e) {  // a full disk: NOT GRADED, never a score
        std::error_code ec;
        fs::remove_all(workDir, ec);  // the part copied: the space the records still need
        StudentWork s;
        s.name = submissionName(path);
        s.error = e.what();
        s.platformFailure = true;
        return s;
    }
}

StudentWork intakeForAssignment(const Assignment& a, const std::string& path,
                                const std::string& workDir) {
    std::set<std::string> listed;
    for (const AssignmentStage* st : a.due()) listed.insert(st->files.begin(), st->files.end());
    StudentWork s = intakeSubmission(path, workDir, dueStageNames(a), listed, a.ownCheckReport);
    std::vector<std::string> more = unlistedFileNotes(a, s);
    s.notes.insert(s.notes.end(), more.begin(), more.end());
    return s;
}

}  // namespace sl
