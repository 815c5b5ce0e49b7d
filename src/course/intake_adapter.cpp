#include "course/intake_adapter.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>

#include "course/archive.h"
#include "io/files.h"
#include "stages/stage.h"

namespace sl {

namespace fs = std::filesystem;

bool StudentWork::has(const std::string& rel) const {
    return std::find(files.begin(), files.end(), rel) != files.end();
}

namespace {

bool isJunk(const std::string& name) {
    return name == "__MACOSX" || name == ".DS_Store" || name == "Thumbs.db" || name == ".git" ||
           name.back() == '~' ||
           (name.size() > 4 && name.compare(name.size() - 4, 4, ".swp") == 0) ||
           name.rfind("._", 0) == 0;
}

bool endsWithZip(const std::string& name) {
    if (name.size() < 4) return false;
    std::string ext = name.substr(name.size() - 4);
    std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
    return ext == ".zip";
}

std::vector<std::string> entriesOf(const std::string& dir) {
    std::vector<std::string> out;
    DIR* d = ::opendir(dir.c_str());
    if (!d) return out;
    while (dirent* e = ::readdir(d)) {
        std::string n = e->d_name;
        if (n != "." && n != ".." && !isJunk(n)) out.push_back(n);
    }
    ::closedir(d);
    std::sort(out.begin(), out.end());
    return out;
}

bool isStageFolder(const std::string& name) {
    return name == "common" || findStage(name) != nullptr;
}

struct Copy {
    UnpackLimits limits;
    std::size_t files = 0, bytes = 0;
    std::string error;
    std::vector<std::string>* notes;
};

// Regular files of `from` into `to`, recursively, bounded; links and devices skipped.
void copyTree(const std::string& from, const std::string& to, const std::string& rel, int depth,
              Copy& c) {
    if (depth > 8) return;
    for (const std::string& n : entriesOf(from)) {
        if (!c.error.empty()) return;
        std::string src = from + "/" + n, dst = to + "/" + n, r = rel.empty() ? n : rel + "/" + n;
        struct stat st;
        if (::lstat(src.c_str(), &st) != 0) continue;
        if (S_ISLNK(st.st_mode)) {
            c.notes->push_back("'" + printableName(r) + "' is a link: not used");
        } else if (S_ISDIR(st.st_mode)) {
            ::mkdir(dst.c_str(), 0700);
            copyTree(src, dst, r, depth + 1, c);
        } else if (S_ISREG(st.st_mode)) {
            if (++c.files > c.limits.maxEntries) {
                c.error = "more than " + std::to_string(c.limits.maxEntries) + " files";
                return;
            }
            std::string text;
            std::string err = readRegularFile(src, c.limits.maxFileBytes, text, true);
            if (!err.empty()) {
                c.notes->push_back("'" + printableName(r) + "': " + err + ": not used");
                continue;
            }
            c.bytes += text.size();
            if (c.bytes > c.limits.maxTotalBytes) {
                c.error = "more than " + std::to_string(c.limits.maxTotalBytes >> 20) + " MB";
                return;
            }
            err = writeFileAtomically(dst, text.data(), text.size());
            if (!err.empty()) c.error = err;
        }
    }
}

void listFiles(const std::string& root, const std::string& rel, std::vector<std::string>& out) {
    for (const std::string& n : entriesOf(root + (rel.empty() ? "" : "/" + rel))) {
        std::string r = rel.empty() ? n : rel + "/" + n;
        struct stat st;
        if (::lstat((root + "/" + r).c_str(), &st) != 0) continue;
        if (S_ISDIR(st.st_mode))
            listFiles(root, r, out);
        else if (S_ISREG(st.st_mode))
            out.push_back(r);
    }
}

}  // namespace

std::string submissionName(const std::string& path) {
    std::string p = path;
    while (p.size() > 1 && p.back() == '/') p.pop_back();
    std::string base = p.substr(p.find_last_of('/') + 1);
    if (endsWithZip(base)) base.resize(base.size() - 4);
    return base;
}

StudentWork intakeSubmission(const std::string& path, const std::string& workDir) {
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
    int zips = 0;
    if (S_ISREG(st.st_mode) && endsWithZip(path)) {
        std::string err = unpackZip(path, workDir + "/unpacked");
        if (!err.empty()) {
            s.error = printableName(s.name) + ".zip refused: " + err;
            return s;
        }
        root = workDir + "/unpacked";
        ++zips;
    } else if (S_ISDIR(st.st_mode)) {
        root = path;
    } else {
        s.error = printableName(path) + ": neither a folder nor a .zip";
        return s;
    }
    // Wrapper folders (a zip of "jdoe_lab4/"), and a lone zip inside a folder (Gradescope keeps
    // an uploaded zip as it is): descend a few levels.
    for (int level = 0; level < 4; ++level) {
        std::vector<std::string> entries = entriesOf(root);
        if (entries.size() != 1) break;
        std::string only = root + "/" + entries[0];
        if (::lstat(only.c_str(), &st) != 0) break;
        if (S_ISDIR(st.st_mode) && !isStageFolder(entries[0])) {
            s.notes.push_back("the work was inside '" + printableName(entries[0]) +
                              "/': used from there");
            root = only;
        } else if (S_ISREG(st.st_mode) && endsWithZip(entries[0]) && zips < 2) {
            std::string target = workDir + "/unpacked" + std::to_string(++zips);
            std::string err = unpackZip(only, target);
            if (!err.empty()) {
                s.error = printableName(entries[0]) + " refused: " + err;
                return s;
            }
            s.notes.push_back("unpacked '" + printableName(entries[0]) + "'");
            root = target;
        } else {
            break;
        }
    }
    // The snapshot: a private copy of the regular files, graded instead of the original.
    std::string snapshot = workDir + "/snapshot";
    ::mkdir(snapshot.c_str(), 0700);
    Copy c;
    c.notes = &s.notes;
    copyTree(root, snapshot, "", 0, c);
    if (!c.error.empty()) {
        s.error = printableName(s.name) + " refused: " + c.error;
        return s;
    }
    s.overlay = snapshot;
    listFiles(snapshot, "", s.files);
    return s;
}

}  // namespace sl
