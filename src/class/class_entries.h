// A class folder read as `grade` reads it (docs/robustness.md, "A class folder"): each entry's
// kind by lstat, never through a link; only real folders and regular files are hand-ins; a link
// or a device is that hand-in refused; the intake's one junk list leaves entries out, and every
// entry left out is named. Each hand-in gets a gradebook name and a file name (its record, work
// folder and page) that no other hand-in can share, whatever bytes its name holds.
#pragma once

#include <string>
#include <vector>

namespace sl {

struct ClassEntry {
    std::string path;     // SUBMISSIONS/<entry>
    std::string entry;    // the entry's exact name
    std::string student;  // the gradebook's name: `entry` without ".zip", or `entry` where
                          // another entry has that name (`ann/` and `ann.zip`)
    std::string key;      // a file name for `student`: itself when it is a plain short name,
                          // else its plain part with '+' and a hash of the exact name
    std::string refusal;  // "" or why it is not taken in (a link, a device): an ERROR row
};

struct ClassListing {
    std::vector<ClassEntry> handIns;   // sorted by entry name
    std::vector<std::string> skipped;  // "NAME (why)", for the summary and the class page
};

// The entries of the folder `submissions` (which must be one). Throws UsageError when it cannot
// be read.
ClassListing listClass(const std::string& submissions);

// The file name kept for the gradebook name `student` ("" never).
std::string recordKey(const std::string& student);

// Refuses (UsageError, one line) an --out that is the submissions folder, lies inside it or
// holds it, however either is spelled (links and `..` resolved).
void refuseOverlap(const std::string& submissions, const std::string& out);

}  // namespace sl
