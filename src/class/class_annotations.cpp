#include "class/class_annotations.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <set>

#include "class/copy_flags.h"
#include "class/copy_pairs.h"
#include "course/release.h"
#include "gradebook/adjustments.h"
#include "gradebook/late_policy.h"
#include "io/files.h"
#include "io/usage_error.h"

namespace sl {

namespace {

// --roster's file, read before any work so that a malformed one costs nothing (exit 2).
std::optional<Roster> rosterOf(const ClassGradeArgs& args) {
    if (args.roster.empty()) return std::nullopt;
    return loadRoster(args.roster);
}

// --times's manifest, read before any work (exit 2 when malformed, or without a late policy).
std::map<std::string, long long> timesOf(const ClassGradeArgs& args, const Assignment& a) {
    if (args.times.empty()) return {};
    if (!a.late)
        throw UsageError("--times: " + printableName(args.assignment) +
                         " has no late policy (\"late\", docs/assignment.md)");
    return loadTimes(args.times);
}

// The late record of hand-in `name` at `entry` under the assignment's policy: its time from
// --times, else the newest time of its files (the record says which).
std::optional<LateRecord> lateOf(const Assignment& a, const std::map<std::string, long long>& times,
                                 const std::string& name, const std::string& entry,
                                 const StudentRecord& r) {
    if (!a.late) return std::nullopt;
    if (auto it = times.find(name); it != times.end())
        return lateFor(*a.late, it->second, "--times", r.maxScore, r.score);
    std::optional<long long> t = newestFileTime(entry);
    if (!t) return std::nullopt;
    return lateFor(*a.late, *t, "file times", r.maxScore, r.score);
}

// The class's adjustments (--adjust, or those kept in DIR/adjustments.csv by an earlier run).
std::map<std::string, std::vector<Adjustment>> adjustmentsOf(
    const ClassGradeArgs& args, const Assignment& a, const std::vector<std::string>& names) {
    std::vector<std::string> stages;
    for (const AssignmentStage* st : a.due()) {
        stages.push_back(st->stage);
        stages.push_back(st->stage + "/" + st->tree);
    }
    return loadAdjustments(args.adjust, args.out + "/adjustments.csv", names, stages);
}

}  // namespace

void addCopyFlags(ClassAnnotations& c, const Assignment& a, const std::vector<std::string>& names,
                  const std::vector<std::string>& files, const std::string& out,
                  const SolutionTrees& trees) {
    std::map<std::string, std::string> solutions, starters;
    for (const AssignmentStage* st : a.due())
        for (const std::string& f : st->files) {
            std::string text;
            if (!readRegularFile(trees.root(st->tree) + "/" + f, 1u << 20, text).empty()) continue;
            solutions[f] = text;
            try {
                starters[f] = stripSolutions(text, f);
            } catch (const std::exception&) {  // markers out of place: the release refuses it
            }
        }
    std::vector<HandInFiles> handIns;
    for (std::size_t k = 0; k < names.size(); ++k) {
        HandInFiles h{names[k], {}};
        for (const auto& [f, solution] : solutions) {
            std::string text;
            if (readRegularFile(out + "/work/" + files[k] + "/snapshot/" + f, 1u << 20, text, true)
                    .empty())
                h.files[f] = text;
        }
        handIns.push_back(std::move(h));
    }
    c.flags.clear();
    c.solutionCopies.clear();
    for (const CopyFlag& f : findCopies(handIns, solutions, starters)) {
        c.flags[f.student].push_back(f.text());
        if (f.other.empty()) c.solutionCopies.push_back(f);
    }
    c.pairs = copyPairs(handIns, starters);
}

ClassAnnotations readAnnotations(const ClassGradeArgs& args, const Assignment& a,
                                 const std::vector<std::string>& names) {
    ClassAnnotations c;
    c.roster = rosterOf(args);
    for (auto& [given, time] : timesOf(args, a)) {  // a name as shown names its hand-in too
        const std::string* name = handInNamed(names, given);
        c.times[name ? *name : given] = time;
    }
    // A time for a name the class does not hold is a typing error or a missing hand-in: said.
    const std::set<std::string> inClass(names.begin(), names.end());
    std::vector<std::string> unknown;
    for (const auto& [name, time] : c.times)
        if (!inClass.count(name)) unknown.push_back(name);
    if (!unknown.empty()) {
        std::cout << "warning: --times: " << unknown.size()
                  << (unknown.size() == 1 ? " entry names" : " entries name")
                  << " no hand-in in the class (unused):";
        for (std::size_t k = 0; k < unknown.size() && k < 10; ++k)
            std::cout << " " << printableName(unknown[k].substr(0, 64));
        if (unknown.size() > 10) std::cout << " and " << unknown.size() - 10 << " more";
        std::cout << "\n";
    }
    c.adjustments = adjustmentsOf(args, a, names);
    return c;
}

void warnOnDownloadTimes(const ClassAnnotations& c, const Assignment& a,
                         const std::vector<std::string>& names,
                         const std::vector<std::string>& entries) {
    if (!a.late) return;
    std::vector<long long> fileTimes;
    for (std::size_t k = 0; k < names.size() && k < entries.size(); ++k)
        if (!c.times.count(names[k]))
            if (std::optional<long long> t = newestFileTime(entries[k])) fileTimes.push_back(*t);
    if (!looksLikeDownload(*a.late, fileTimes)) return;
    const auto [first, last] = std::minmax_element(fileTimes.begin(), fileTimes.end());
    std::cout << "warning: the file times of " << fileTimes.size() << " hand-ins"
              << (c.times.empty() ? "" : " not in --times")
              << " all lie after the deadline, within " << (*last - *first + 59) / 60
              << " min of each other (" << isoUtc(*first) << " to " << isoUtc(*last)
              << "): that looks like when the class was downloaded, and each is charged late; "
                 "give when each was handed in with --times times.csv (hand-in,time; "
                 "docs/assignment.md \"Late policy\")\n";
}

// What the class adds to a kept record when outputs are drawn (its roster entry, its copy
// flags, its lateness, its adjustments): true when that changed it, so it is written again.
bool annotateRecord(const ClassAnnotations& c, const Assignment& a, const std::string& name,
                    const std::string& entry, StudentRecord& r) {
    const auto& roster = c.roster;
    const auto& flags = c.flags;
    const auto& times = c.times;
    const auto& adjustments = c.adjustments;
    const std::optional<LateRecord> late = lateOf(a, times, name, entry, r);
    bool changed = roster && attachRoster(*roster, name, r);
    auto given = adjustments.find(name);
    std::vector<Adjustment> mineAdjusted =
        given == adjustments.end() ? std::vector<Adjustment>() : given->second;
    auto sameAdjustments = [](const std::vector<Adjustment>& x, const std::vector<Adjustment>& y) {
        if (x.size() != y.size()) return false;
        for (std::size_t i = 0; i < x.size(); ++i)
            if (x[i].stage != y[i].stage || x[i].points != y[i].points ||
                x[i].reason != y[i].reason)
                return false;
        return true;
    };
    if (!sameAdjustments(mineAdjusted, r.adjustments)) {
        r.adjustments = mineAdjusted;
        changed = true;
    }
    auto same = [](const std::optional<LateRecord>& x, const std::optional<LateRecord>& y) {
        return x.has_value() == y.has_value() &&
               (!x || (x->handedIn == y->handedIn && x->source == y->source && x->days == y->days &&
                       x->capped == y->capped && std::abs(x->penalty - y->penalty) < 1e-9));
    };
    if (!same(late, r.late)) {
        r.late = late;
        changed = true;
    }
    auto it = flags.find(name);
    std::vector<std::string> mine = it == flags.end() ? std::vector<std::string>() : it->second;
    if (mine != r.flags) {
        r.flags = mine;
        changed = true;
    }
    return changed;
}

}  // namespace sl
