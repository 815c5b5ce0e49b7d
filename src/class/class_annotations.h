// What a class adds to its students' records when the outputs are drawn, never by grading
// anyone again (docs/assignment.md): the roster's entry, copy flags, the late policy's
// penalty and TAs' adjustments. A record whose annotations change is written again.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "class/class_grade.h"
#include "class/copy_pairs.h"
#include "course/release.h"
#include "gradebook/roster.h"

namespace sl {

struct ClassAnnotations {
    std::optional<Roster> roster;                           // --roster
    std::map<std::string, std::vector<std::string>> flags;  // by hand-in: copy flags
    std::vector<CopyPair> pairs;             // every pair with due code in common, ranked
    std::vector<CopyFlag> solutionCopies;    // the files equal to the published solution
    std::map<std::string, long long> times;  // --times: hand-in -> time
    std::map<std::string, std::vector<Adjustment>> adjustments;  // --adjust, or kept ones
};

// The roster, --times and the adjustments of `args` (a malformed one: UsageError, exit 2),
// read before any work; `names`: the class's hand-in names. Flags come later (addCopyFlags).
ClassAnnotations readAnnotations(const ClassGradeArgs& args, const Assignment& a,
                                 const std::vector<std::string>& names);

// The class's copy flags (`c.flags` by hand-in name, `c.pairs`, `c.solutionCopies`), from the
// due files of each hand-in's snapshot under `out`/work/`files[k]`/snapshot
// (class/copy_flags.h, copy_pairs.h): against the shipped solution (whole file) and between
// classmates by pair, never for the starter.
void addCopyFlags(ClassAnnotations& c, const Assignment& a, const std::vector<std::string>& names,
                  const std::vector<std::string>& files, const std::string& out,
                  const SolutionTrees& trees);

// Without --times for them, when the file times of the hand-ins at `entries` (named `names`)
// look like a download (gradebook/late_policy.h looksLikeDownload), one warning line on stdout
// saying so and how to give the times (--times). Nothing is changed: the policy still applies.
void warnOnDownloadTimes(const ClassAnnotations& c, const Assignment& a,
                         const std::vector<std::string>& names,
                         const std::vector<std::string>& entries);

// Gives `r` (hand-in `name`, at `entry` in the class folder) its roster entry, copy flags, late
// record (from --times, else its files' newest time) and adjustments: true when that changed
// it, so that it is written again.
bool annotateRecord(const ClassAnnotations& c, const Assignment& a, const std::string& name,
                    const std::string& entry, StudentRecord& r);

}  // namespace sl
