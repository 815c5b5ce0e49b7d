#include "class/class_entries.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include "course/intake_adapter.h"
#include "grade/intake.h"
#include "io/content_hash.h"
#include "io/files.h"
#include "io/usage_error.h"

namespace sl {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kPlainMax = 64;  // a key's plain part; far below any file system's limit

bool plainChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_';
}

bool isPlain(const std::string& name) {
    return !name.empty() && name.size() <= kPlainMax && name[0] != '.' &&
           std::all_of(name.begin(), name.end(), plainChar);
}

// Why the entry of kind `mode` is refused as a hand-in, or "" when it is one.
std::string refusalFor(const std::string& entry, mode_t mode) {
    if (S_ISDIR(mode) || S_ISREG(mode)) return "";
    std::string shown = printableName(entry);
    if (S_ISLNK(mode))
        return shown +
               ": a link, not a hand-in (links are never followed): put the folder or "
               ".zip itself in the class folder";
    return shown + ": not a folder or a file (a device, pipe or socket): not a hand-in";
}

// Each entry's gradebook name: the name without ".zip" while no other entry has it, else the
// exact entry name (unique in a folder). Repeated until no two are equal.
void nameStudents(std::vector<ClassEntry>& entries) {
    for (auto& e : entries) e.student = submissionName(e.entry);
    for (bool again = true; again;) {
        again = false;
        std::map<std::string, int> count;
        for (const auto& e : entries) ++count[e.student];
        for (auto& e : entries)
            if (count[e.student] > 1 && e.student != e.entry) {
                e.student = e.entry;
                again = true;
            }
    }
}

}  // namespace

std::string recordKey(const std::string& student) {
    if (isPlain(student)) return student;
    std::string plain;
    for (char c : student.substr(0, kPlainMax / 2)) plain += plainChar(c) ? c : '_';
    if (!plain.empty() && plain[0] == '.') plain[0] = '_';
    // '+' is never in a plain key: a hashed key cannot equal another student's plain one.
    return plain + "+" + fnv1aHex(student);
}

ClassListing listClass(const std::string& submissions) {
    ClassListing out;
    DIR* dir = ::opendir(submissions.c_str());
    if (!dir) throw UsageError("grade: cannot read the folder " + printableName(submissions));
    const int dfd = ::dirfd(dir);
    while (dirent* d = ::readdir(dir)) {
        std::string name = d->d_name;
        if (name == "." || name == "..") continue;
        if (std::string why = junkReason(name); !why.empty()) {
            out.skipped.push_back(printableName(name) + " (" + why + ")");
            continue;
        }
        struct stat st;
        ClassEntry e;
        e.entry = name;
        e.path = submissions + "/" + name;
        if (::fstatat(dfd, name.c_str(), &st, AT_SYMLINK_NOFOLLOW) != 0)
            e.refusal = printableName(name) + ": cannot be read: not a hand-in";
        else
            e.refusal = refusalFor(name, st.st_mode);
        out.handIns.push_back(e);
    }
    ::closedir(dir);
    std::sort(out.handIns.begin(), out.handIns.end(),
              [](const ClassEntry& a, const ClassEntry& b) { return a.entry < b.entry; });
    std::sort(out.skipped.begin(), out.skipped.end());
    nameStudents(out.handIns);
    std::set<std::string> taken;
    for (auto& e : out.handIns) {
        e.key = recordKey(e.student);
        // Two hashed keys alike (64-bit FNV of two names): the later one numbered.
        for (int k = 2; !taken.insert(e.key).second; ++k)
            e.key = recordKey(e.student) + "+" + std::to_string(k);
    }
    return out;
}

void refuseOverlap(const std::string& submissions, const std::string& out) {
    const bool outInSubs = liesWithin(out, submissions), subsInOut = liesWithin(submissions, out);
    std::string why;
    if (outInSubs && subsInOut)
        why = " is the submissions folder";
    else if (outInSubs)
        why = " lies inside the submissions folder " + printableName(submissions) +
              " (its outputs would be graded as students)";
    else if (subsInOut)
        why = " holds the submissions folder " + printableName(submissions);
    if (!why.empty())
        throw UsageError("--out: " + printableName(out) + why + ": give a folder outside it");
}

}  // namespace sl
