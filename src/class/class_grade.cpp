#include "class/class_grade.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>

#include "class/class_annotations.h"
#include "class/class_entries.h"
#include "class/class_out.h"
#include "class/class_progress.h"
#include "course/intake_adapter.h"
#include "course/solution_check.h"
#include "course/student_grade.h"
#include "feedback/class_page.h"
#include "feedback/feedback_html.h"
#include "grade/check_run.h"  // drawSeed
#include "gradebook/gradebook_exports.h"
#include "gradebook/roster.h"
#include "io/box.h"
#include "io/content_hash.h"
#include "io/files.h"
#include "io/usage_error.h"
#include "sandbox/job_fanout.h"
#include "sandbox/private_dir.h"
#include "stages/displaced_bounds.h"
#include "stages/expectations.h"

namespace sl {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// A file's identity and version, to read a record only when it is new: one written again (a new
// file, renamed into place) differs in its inode.
struct FileStamp {
    dev_t dev = 0;
    ino_t ino = 0;
    off_t size = 0;
    long mtimeSec = 0, mtimeNsec = 0;
    bool operator==(const FileStamp& o) const {
        return dev == o.dev && ino == o.ino && size == o.size && mtimeSec == o.mtimeSec &&
               mtimeNsec == o.mtimeNsec;
    }
};

std::optional<FileStamp> stampOf(const std::string& path) {
    struct stat st;
    if (::lstat(path.c_str(), &st) != 0) return std::nullopt;
    return FileStamp{st.st_dev, st.st_ino, st.st_size, long(st.st_mtim.tv_sec),
                     long(st.st_mtim.tv_nsec)};
}

// A job that could not write for want of space exits with this (its log may be lost with it).
constexpr int kJobDiskFull = 4;

// A record as kept in OUT/students/: its JSON with "record_hash", the FNV-1a of the rest of it
// (compact, keys sorted), so a record changed since it was written (a score raised by hand) is
// told from one grade wrote. A change detector, not a signature: anyone may recompute it.
std::string sealedRecordText(const StudentRecord& r) {
    json j = keptRecordJson(r);
    j["record_hash"] = fnv1aHex(j.dump(-1, ' ', false, json::error_handler_t::replace));
    return j.dump(1, ' ', false, json::error_handler_t::replace) + "\n";
}

// The record kept at `path` for the student named exactly `student`, if it can be read as one
// and its content hash matches; else, when given, `setAside` says why one there is not kept (a
// record kept by an older shadowlab, or edited since it was written).
std::optional<StudentRecord> keptRecord(const std::string& path, const std::string& student,
                                        std::string* setAside = nullptr) {
    std::string text;
    if (!readRegularFile(path, 64u << 20, text, true).empty()) return std::nullopt;
    try {
        json j = json::parse(text);
        const std::string hash = j.value("record_hash", "");
        j.erase("record_hash");
        StudentRecord r = recordFromJson(j);
        if (r.student != student) return std::nullopt;  // another name's record: not theirs
        if (hash != fnv1aHex(j.dump(-1, ' ', false, json::error_handler_t::replace))) {
            if (setAside) *setAside = "its record does not match its content hash (edited?)";
            return std::nullopt;
        }
        return r;
    } catch (const FormatError& e) {  // its rows may name lessons the way it did: grade again
        if (setAside && e.older()) *setAside = "kept by an older shadowlab";
        return std::nullopt;
    } catch (const std::exception&) {  // malformed, or a lesson no longer in the data
        return std::nullopt;
    }
}

// The hand-in's content as given: a zip's bytes, a folder's regular files (io/content_hash.h);
// of a link or a device, only its kind and, for a link, where it points (never followed).
std::string handInHash(const std::string& path) {
    struct stat st;
    if (::lstat(path.c_str(), &st) != 0) return "";
    if (S_ISDIR(st.st_mode)) return contentHash(path);
    if (S_ISLNK(st.st_mode)) {
        char target[4096];
        ssize_t n = ::readlink(path.c_str(), target, sizeof target);
        return fnv1aHex("link: " + std::string(target, n > 0 ? std::size_t(n) : 0));
    }
    if (!S_ISREG(st.st_mode)) return fnv1aHex("mode: " + std::to_string(st.st_mode));
    std::string bytes;
    std::string err = readRegularFile(path, std::size_t(1) << 30, bytes, true);
    return fnv1aHex(err.empty() ? bytes : "unreadable: " + err);
}

// Why a student is graded in this run: "" when their kept record stands, "new" when there is
// none, else why it is set aside (`setAside`: why keptRecord did not keep the one there).
std::string whyGrade(const std::optional<StudentRecord>& kept, const std::string& setAside,
                     const std::string& handIn, const std::string& assignment, std::uint64_t seed,
                     bool asked) {
    if (asked) return "asked for (--regrade)";
    if (!kept) return setAside.empty() ? "new" : setAside;
    if (!kept->graded()) return "not graded last time";
    if (kept->assignmentHash != assignment) return "the assignment changed";
    if (kept->handInHash != handIn) return "the hand-in changed";
    if (kept->seed != seed) return "graded in another displaced view than the class's seed";
    return "";
}

std::string skippedList(const ClassListing& listing) {
    std::string list;
    for (const std::string& s : listing.skipped) list += (list.empty() ? "" : ", ") + s;
    return list;
}

std::string duration(double s) {
    char t[32];
    if (s >= 90)
        std::snprintf(t, sizeof t, "%d min %02d s", int(s) / 60, int(s) % 60);
    else
        std::snprintf(t, sizeof t, "%.0f s", s);
    return t;
}

// The time left, under 10 s in tenths: a whole second is more than a quarter of what is left
// under 4 s (0.7 s left was said "1 s", 43 % off, on the last lines of a class).
std::string timeLeftText(double s) {
    if (s >= 9.95) return duration(s);
    char t[32];
    std::snprintf(t, sizeof t, "%.1f s", std::max(0.0, s));
    return t;
}

// The class's displaced-view seed, one for every record: --seed, else the seed most kept records
// share (a rerun, --regrade NAME: a student graded with another is graded again), else drawn
// now. A --seed other than the kept records' is refused unless --regrade-all grades everyone in
// the new views: two seeds in one class would hold students to different views.
std::uint64_t classSeed(const ClassGradeArgs& args, const std::vector<std::string>& recordPaths,
                        const std::vector<std::string>& students) {
    std::map<std::uint64_t, std::size_t> kept;  // seed: records
    for (std::size_t k = 0; k < recordPaths.size(); ++k)
        if (std::optional<StudentRecord> r = keptRecord(recordPaths[k], students[k]); r && r->seed)
            ++kept[*r->seed];
    auto most = std::max_element(kept.begin(), kept.end(),
                                 [](const auto& a, const auto& b) { return a.second < b.second; });
    if (!args.seed) {
        if (kept.empty()) return drawSeed();
        std::cout << "the class's seed " << most->first << " (kept from its records)\n";
        return most->first;
    }
    if (kept.empty() || most->first == *args.seed) return *args.seed;
    if (!args.regradeAll)
        throw UsageError("grade: --seed " + std::to_string(*args.seed) + ": the class in " +
                         printableName(args.out) + " was graded with seed " +
                         std::to_string(most->first) +
                         " (one seed a class): leave --seed out to keep it, or add --regrade-all "
                         "to grade every student again with the new one");
    std::cout << "the class's seed is now " << *args.seed << " (was " << most->first
              << "): --regrade-all grades every student in the new displaced views\n";
    return *args.seed;
}

// What a passed solution check saw: the assignment's text, the solution trees' files and the
// expectations they were graded by. A rerun (a class graded in parts, a regrade, a platform
// failure retried) with the same key skips the check: the solution earns the same points.
std::string solutionCheckKey(const std::string& assignmentHash, const SolutionTrees& trees,
                             std::uint64_t seed) {
    return assignmentHash + " " + contentHash(trees.root("core")) + " " +
           contentHash(trees.root("legacy")) + " " + handInHash(expectationsPath()) + " " +
           handInHash(displacedBoundsPath()) + " seed " + std::to_string(seed);
}

bool solutionCheckPassed(const std::string& out, const std::string& key) {
    std::string text;
    return readRegularFile(out + "/solution_check.txt", 4096, text, true).empty() &&
           text == key + "\n";
}

// The record of a student on the roster who handed nothing in: every due stage MISSING, 0
// points, the note "no hand-in".
StudentRecord noHandInRecord(const Assignment& a, const RosterEntry& e) {
    StudentWork none;
    none.name = e.handIn;
    GradingPlan plan = planStudent(a, none, std::nullopt);
    std::vector<StageRecord> stages;
    for (const StagePlan& p : plan.stages) stages.push_back(stageRecord(p, nullptr, ""));
    none.notes.push_back("no hand-in");
    StudentRecord r = buildRecord(plan, none, stages, 0);
    r.roster = e.who;
    return r;
}

// The roster's students with no hand-in get a record and a page ("no hand-in", every stage
// MISSING) so the gradebook is complete.
void addRosterStudents(const Roster& roster, const Assignment& a,
                       const std::vector<std::string>& names, const std::string& out,
                       std::vector<StudentRecord>& records, std::vector<std::string>& pages) {
    for (const RosterEntry* e : rosterWithoutHandIn(roster, names)) {
        records.push_back(noHandInRecord(a, *e));
        pages.push_back("feedback/" + recordKey(e->handIn) + ".html");
        writeOrThrow(out + "/" + pages.back(), studentPage(records.back()));
    }
}

// Hand-ins the roster does not list, named in one line before any grading (known from the names).
void sayStrangers(const Roster& roster, const std::vector<std::string>& names) {
    std::vector<std::string> strangers = handInsNotOnRoster(roster, names);
    if (strangers.empty()) return;
    std::cout << notOnRosterLine(strangers) << "\n";
}

// The class as found: its hand-ins in the listing's order, each with its gradebook name, its
// file key (its record's and page's name), the intake's refusal and its content hash.
struct ClassInput {
    Assignment a;
    std::string assignmentHash;  // a record stands only for the same text (and hand-in)
    ClassListing listing;
    std::vector<std::string> entries, names, files, refusals, hashes;
};

// One `grade` run, step by step: run() reads as the page of what grade does.
class ClassGrading {
  public:
    explicit ClassGrading(const ClassGradeArgs& args) : args_(args), settings_(args.settings) {}
    int run();

  private:
    void readClass();
    bool solutionPassedBefore(const std::string& checkKey);
    void chooseStudents();
    void takeIn();
    int gradeInJobs(OutLock& lock);
    int gradeShare(int job, int jobs, OutLock& lock);
    void reportFinished(double seconds, const std::optional<double>& rowsLeft);
    void writeStudentOutputs(std::size_t k, const StudentRecord& r, bool annotated);
    std::size_t writeOutputs();
    void sayGraded(std::size_t notGraded);
    std::string recordPath(std::size_t k) const {
        return args_.out + "/students/" + in_.files[k] + ".json";
    }
    std::string progressPath(int job) const {
        return args_.out + "/logs/job-" + std::to_string(job) + ".progress";
    }
    double secondsSinceStart() const {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }
    bool isFresh(std::size_t k, std::optional<StudentRecord>& r) const {
        r = keptRecord(recordPath(k), in_.names[k]);
        return r && r->handInHash == in_.hashes[k] && r->assignmentHash == in_.assignmentHash;
    }

    const ClassGradeArgs& args_;
    GradeSettings settings_;
    ClassInput in_;
    SolutionTrees trees_;
    ClassAnnotations annotations_;
    std::vector<std::size_t> todo_;  // the students graded in this run
    std::vector<StudentWork> subs_;  // their snapshots (by student index)
    std::set<std::size_t> reported_;
    std::map<std::size_t, std::optional<FileStamp>> recordRead_;  // the record as last read
    std::set<std::size_t> pageWritten_;  // pages written as their records came back
    std::string lastLine_;  // the last student's line, said once the class's outputs are written
    Pace pace_;
    std::size_t jobs_ = 1;
    std::chrono::steady_clock::time_point start_;
};

int ClassGrading::run() {
    if (args_.jobs < 0 || args_.jobs > 64) throw UsageError("--jobs: give 1 to 64, or auto");
    readClass();
    {
        std::vector<std::string> kept;
        for (std::size_t k = 0; k < in_.entries.size(); ++k) kept.push_back(recordPath(k));
        settings_.seed = classSeed(args_, kept, in_.names);
    }
    // Mesa's shader cache, one for the whole run (the solution check, every job, every worker):
    // our shipped programs are compiled once per class instead of once per student, lesson and
    // view, and a student's own once per student. Keyed by the shader's text and the driver, so
    // no hand-in is served another's program; private, gone with the run.
    std::optional<PrivateDir> shaderCache;
    shaderCache.emplace("shadowlab-shader-cache");
    useShaderCacheFolder(shaderCache->path());
    trees_ = solutionTrees(args_.solutions);
    const std::string checkKey = solutionCheckKey(in_.assignmentHash, trees_, *settings_.seed);
    const bool checked = solutionPassedBefore(checkKey);
    if (!checked)  // said once what the files alone show has passed (never before its refusal)
        verifySolution(in_.a, trees_, settings_, [&] {
            std::cout << "grading the solution (" << trees_.describe() << ") by "
                      << printableName(args_.assignment) << " first\n"
                      << std::flush;
        });
    createOut(args_.out);
    OutLock lock(args_.out);
    makeOutFolders(args_.out);
    if (!checked) {
        const std::string line = checkKey + "\n";
        std::string err =
            writeFileAtomically(args_.out + "/solution_check.txt", line.data(), line.size());
        if (!err.empty() && diskFull(errno)) throwWriteError(err);
        if (!err.empty()) throw std::runtime_error("grade: " + err);
    }
    // The roster, --times and the adjustments: read (and refused, exit 2) before any work.
    annotations_ = readAnnotations(args_, in_.a, in_.names);
    warnOnDownloadTimes(annotations_, in_.a, in_.names, in_.entries);
    chooseStudents();
    if (annotations_.roster) sayStrangers(*annotations_.roster, in_.names);
    takeIn();
    start_ = std::chrono::steady_clock::now();
    // The copy flags from the snapshots (takeIn's, and earlier runs' for kept records), before
    // any grading: each student's record and page are then final as the student comes back, and
    // after the last one only the class's page, gradebooks and exports are left (issue 39).
    addCopyFlags(annotations_, in_.a, in_.names, in_.files, args_.out, trees_);
    int exitCode = gradeInJobs(lock);
    std::size_t notGraded = 0;
    try {
        notGraded = writeOutputs();
    } catch (...) {  // a full disk: the last student's line is still said, before the error's
        std::cout << lastLine_ << std::flush;
        throw;
    }
    if (notGraded > 0) exitCode = 3;
    shaderCache.reset();  // removing it is part of the run
    sayGraded(notGraded);
    return exitCode;
}

void ClassGrading::readClass() {
    in_.a = loadAssignment(args_.assignment);
    std::string assignmentText;
    readRegularFile(args_.assignment, 1u << 20, assignmentText);
    in_.assignmentHash = fnv1aHex(assignmentText);
    struct stat st;
    if (::stat(args_.submissions.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
        throw UsageError(
            "grade: " + printableName(args_.submissions) +
            " is not a folder (give the folder holding one folder or .zip per student)");
    refuseOverlap(args_.submissions, args_.out);
    refuseLinksInOut(args_.out);
    in_.listing = listClass(args_.submissions);
    if (in_.listing.handIns.empty())
        throw UsageError(
            "grade: " + printableName(args_.submissions) + " holds no submission" +
            (in_.listing.skipped.empty() ? "" : " (left out: " + skippedList(in_.listing) + ")"));
    for (const ClassEntry& e : in_.listing.handIns) {
        in_.entries.push_back(e.path);
        in_.names.push_back(e.student);
        in_.files.push_back(e.key);
        in_.refusals.push_back(e.refusal);
    }
    in_.hashes.resize(in_.entries.size());
}

// True when an earlier run passed the same solution check (its key in --out), and says so.
bool ClassGrading::solutionPassedBefore(const std::string& checkKey) {
    if (!solutionCheckPassed(args_.out, checkKey)) return false;
    std::cout << "the solution (" << trees_.describe() << ") passed "
              << printableName(args_.assignment) << " in an earlier run: not graded again\n";
    return true;
}

// Who is graded in this run: the new, the changed and those asked for, each one graded again
// with a line saying why; then the run's header line.
void ClassGrading::chooseStudents() {
    std::set<std::string> regrade;  // the hand-ins --regrade names (exactly, or as shown)
    for (const std::string& wanted : args_.regrade) {
        const std::string* name = handInNamed(in_.names, wanted);
        if (!name)
            throw UsageError("--regrade: no hand-in named '" + printableName(wanted) + "' in " +
                             printableName(args_.submissions));
        regrade.insert(*name);
    }
    const std::size_t n = in_.entries.size();
    std::map<std::string, int> reasons;  // why students are graded in this run
    for (std::size_t k = 0; k < n; ++k) {
        in_.hashes[k] = handInHash(in_.entries[k]);
        const bool asked = args_.regradeAll || regrade.count(in_.names[k]);
        std::string setAside;
        std::optional<StudentRecord> kept = keptRecord(recordPath(k), in_.names[k], &setAside);
        std::string why =
            whyGrade(kept, setAside, in_.hashes[k], in_.assignmentHash, *settings_.seed, asked);
        if (why.empty()) continue;
        todo_.push_back(k);
        ++reasons[why];
        if (why != "new")
            std::cout << "grading " << printableName(escapedName(in_.names[k])) << " again: " << why
                      << "\n";
    }
    std::cout << "grade " << n << " submissions by " << printableName(args_.assignment) << " ("
              << in_.a.name << ")";
    if (todo_.size() < n || reasons.count("new") < reasons.size()) {
        std::cout << ": " << n - todo_.size() << " already graded, " << todo_.size() << " to grade";
        std::string why;
        for (const auto& [reason, count] : reasons)
            why += (why.empty() ? " (" : ", ") + std::to_string(count) + " " + reason;
        if (!why.empty()) std::cout << why << ")";
    }
    std::cout << "\n";
    if (!in_.listing.skipped.empty())
        std::cout << "left out, not hand-ins: " << skippedList(in_.listing) << "\n";
    std::cout << std::flush;
}

// Intake in the parent (no GL here): every pending submission's snapshot, and the folder its
// pictures go to.
void ClassGrading::takeIn() {
    subs_.assign(in_.entries.size(), StudentWork());
    std::map<std::string, std::string> imageDirs;
    for (std::size_t k : todo_) {
        const std::string work = args_.out + "/work/" + in_.files[k];
        if (in_.refusals[k].empty())
            subs_[k] = intakeForAssignment(in_.a, in_.entries[k], work);
        else
            subs_[k].error = in_.refusals[k];  // nothing of it is read, followed or copied
        subs_[k].name = in_.names[k];
        subs_[k].hash = in_.hashes[k];
        std::error_code ec;
        fs::create_directories(work + "/images", ec);
        imageDirs[subs_[k].name] = work + "/images";
    }
    settings_.pictures = true;
    settings_.pagePicturesOnly = true;
    settings_.imageDir = [imageDirs](const StudentWork& s) {
        auto it = imageDirs.find(s.name);
        return it == imageDirs.end() ? std::string() : it->second;
    };
}

// Jobs: child processes, each grading every jobs-th pending student in one worker series with
// one calibration of our shaders, on its share of the cores (a worker with llvmpipe's and the
// figures' threads on every core, twice over, was slower than one job: issue 28). A line each
// time a student is done; 3 when a job failed.
int ClassGrading::gradeInJobs(OutLock& lock) {
    if (todo_.empty()) return 0;
    const int cores = boxCores();
    const int wanted = args_.jobs > 0 ? args_.jobs : boxJobs(kMbPerGradingJob);
    const int jobs = int(std::min<std::size_t>(std::size_t(wanted), todo_.size()));
    std::cout << jobs << (jobs == 1 ? " job" : " jobs") << " on " << cores
              << (cores == 1 ? " core" : " cores")
              << (args_.jobs > 0 ? " (--jobs)" : " (--jobs auto)") << "\n";
    JobFanOut fan(jobs, std::max(1, cores / jobs), "grade job",
                  [&](int j) { return gradeShare(j, jobs, lock); });
    std::vector<std::string> progressFiles;
    for (int j = 0; j < jobs; ++j) progressFiles.push_back(progressPath(j));
    int exitCode = 0, diskFullJobs = 0;
    jobs_ = std::size_t(jobs);
    pace_.outputsRead(in_.entries.size());  // writeOutputs reads every student's record again
    auto poll = [&] {  // read every time, so the pace starts from the first rows that came back
        const double now = secondsSinceStart();
        reportFinished(now, pace_.timeLeft(now, readProgress(progressFiles)));
    };
    while (fan.running()) {
        // Every 0.1 s: a line's time is its record's to within that (0.3 s was a third of the
        // time left on the last lines); a poll is a stat of each record not back yet.
        for (const JobFanOut::Ended& e : fan.reap(std::chrono::milliseconds(100))) {
            if (e.code != 0) exitCode = 3;
            if (e.code == kJobDiskFull) ++diskFullJobs;
        }
        poll();
    }
    poll();
    if (diskFullJobs > 0) {  // one line, not one a student: the outputs would not fit either
        std::size_t lost = todo_.size() - reported_.size();
        throw DiskFullError("grade: the disk under " + printableName(args_.out) + " is full: " +
                            std::to_string(lost) + " of " + std::to_string(todo_.size()) +
                            " students' records could not be written (not graded; what earlier "
                            "runs wrote is kept): free space and rerun grade");
    }
    return exitCode;
}

// In job `job`'s process: its share of the students, graded, each record written as it is done.
int ClassGrading::gradeShare(int job, int jobs, OutLock& lock) {
    lock.closeInJob();
    std::string log = args_.out + "/logs/job-" + std::to_string(job) + ".log";
    // O_NOFOLLOW: a link planted at the log's name is never truncated through.
    int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0644);
    // Its students get no record: named, not graded, exit 3.
    if (fd < 0) return diskFull(errno) ? kJobDiskFull : 3;
    ::dup2(fd, 1);
    ::dup2(fd, 2);
    ::close(fd);
    try {
        std::vector<StudentWork> share;
        std::vector<GradingPlan> plans;
        std::vector<std::size_t> index;
        for (std::size_t i = std::size_t(job); i < todo_.size(); i += std::size_t(jobs)) {
            share.push_back(subs_[todo_[i]]);
            plans.push_back(planStudent(in_.a, share.back(), settings_.seed));
            index.push_back(todo_[i]);
        }
        Calibration calibration(settings_.budget, settings_.backend);
        JobProgress progress(progressPath(job), plans, renderOrder(plans, share));
        gradeStudents(
            plans, share, settings_, calibration,
            [&](std::size_t i, const StageRecord& st) { progress.stageDone(i, st); },
            [&](std::size_t i, StudentRecord r) {
                r.assignmentHash = in_.assignmentHash;
                writeOrThrow(recordPath(index[i]), sealedRecordText(r));
            });
    } catch (const DiskFullError& e) {
        std::cerr << "shadowlab: grade job " << job << ": " << e.what() << "\n";
        return kJobDiskFull;
    }
    return 0;
}

// A line for each student whose record came back since the last call, with the total the pages
// show and the time left at the pace of the rows the jobs rendered (class/class_progress.h); the
// student's record (annotated) and page are written first. The last student's line is held until
// the class's outputs are written: its "0 s" is then true.
void ClassGrading::reportFinished(double seconds, const std::optional<double>& rowsLeft) {
    const std::size_t n = in_.entries.size();
    for (std::size_t i = 0; i < todo_.size(); ++i) {
        const std::size_t k = todo_[i];
        if (reported_.count(k)) continue;
        // A kept record of an earlier run is read once, not at every poll (a class regraded).
        const std::optional<FileStamp> stamp = stampOf(recordPath(k));
        if (!stamp || recordRead_[k] == stamp) continue;
        recordRead_[k] = stamp;
        const double readFrom = secondsSinceStart();
        std::optional<StudentRecord> r;
        if (!isFresh(k, r)) continue;
        const double read = secondsSinceStart() - readFrom;  // what writeOutputs does again
        reported_.insert(k);
        writeStudentOutputs(k, *r,
                            annotateRecord(annotations_, in_.a, in_.names[k], in_.entries[k], *r));
        pace_.recordBack(secondsSinceStart(), i % jobs_, read);  // gradeShare's: every jobs_-th
        const double left = timeLeftWhenSaid(
            rowsLeft ? *rowsLeft
                     : seconds / double(reported_.size()) * double(todo_.size() - reported_.size()),
            seconds, secondsSinceStart());
        char line[512];
        std::snprintf(line, sizeof line,
                      "[student %zu of %zu] %-24s %7.2f / %.2f  %-10s time left about %s\n",
                      n - todo_.size() + reported_.size(), n,
                      printableName(escapedName(in_.names[k])).c_str(),
                      r->graded() ? r->total() : r->score, r->maxScore, statusName(r->status()),
                      reported_.size() == todo_.size() ? "0 s" : timeLeftText(left).c_str());
        if (reported_.size() == todo_.size())
            lastLine_ = line;
        else
            std::cout << line << std::flush;
    }
}

// A student's own outputs as the record comes back: the record again when annotating changed it,
// and the page. A write that fails is left to writeOutputs, which writes it again (and says why).
void ClassGrading::writeStudentOutputs(std::size_t k, const StudentRecord& r, bool annotated) {
    if (annotated) {
        const std::string text = sealedRecordText(r);
        if (!writeFileAtomically(recordPath(k), text.data(), text.size()).empty()) return;
    }
    const std::string page = studentPage(r);
    const std::string path = args_.out + "/feedback/" + in_.files[k] + ".html";
    if (writeFileAtomically(path, page.data(), page.size()).empty()) pageWritten_.insert(k);
}

// The class's outputs from every record (those of earlier runs too): a page per student (but
// those written as their records came back, unchanged since), grades.csv, the LMS gradebooks and
// the class page. Returns how many are not graded.
std::size_t ClassGrading::writeOutputs() {
    const std::size_t n = in_.entries.size();
    std::vector<StudentRecord> records;
    std::vector<std::string> pages;
    std::size_t notGraded = 0;
    for (std::size_t k = 0; k < n; ++k) {
        std::optional<StudentRecord> r;
        if (!isFresh(k, r)) {
            std::cerr << "shadowlab: " << printableName(escapedName(in_.names[k]))
                      << ": no record (its job failed; see " << args_.out
                      << "/logs/): not graded, rerun grade\n";
            ++notGraded;
            continue;
        }
        if (!r->graded()) ++notGraded;
        const bool annotated =
            annotateRecord(annotations_, in_.a, in_.names[k], in_.entries[k], *r);
        if (annotated) writeOrThrow(recordPath(k), sealedRecordText(*r));
        records.push_back(*r);
        pages.push_back("feedback/" + in_.files[k] + ".html");
        if (annotated || !pageWritten_.count(k))
            writeOrThrow(args_.out + "/" + pages.back(), studentPage(*r));
    }
    if (annotations_.roster)
        addRosterStudents(*annotations_.roster, in_.a, in_.names, args_.out, records, pages);
    writeOrThrow(args_.out + "/grades.csv", gradesCsv(records));
    writeOrThrow(args_.out + "/gradebook-canvas.csv", canvasCsv(in_.a.name, records));
    writeOrThrow(args_.out + "/gradebook-moodle.csv", moodleCsv(in_.a.name, records));
    writeOrThrow(args_.out + "/class.html",
                 classPage(in_.a.name, records, pages, in_.listing.skipped,
                           {annotations_.pairs, annotations_.solutionCopies}));
    return notGraded;
}

// The last student's line, held until now, then the run's summary.
void ClassGrading::sayGraded(std::size_t notGraded) {
    const std::size_t n = in_.entries.size();
    std::cout << lastLine_;
    const double seconds = secondsSinceStart();
    std::size_t copyFull = 0;  // hand-ins whose private copy found the disk full (NOT GRADED)
    for (std::size_t k : todo_) copyFull += subs_[k].platformFailure;
    if (copyFull > 0)
        std::cerr << "shadowlab: grade: the disk was full: " << copyFull
                  << (copyFull == 1 ? " hand-in" : " hand-ins")
                  << " could not be copied to be graded (NOT GRADED, not the students' fault): "
                     "free space and rerun grade\n";
    std::cout << "graded " << n - notGraded << " of " << n;
    if (notGraded > 0) std::cout << "; " << notGraded << " not graded: rerun";
    std::cout << " in " << duration(seconds) << ": " << args_.out << "/grades.csv, " << args_.out
              << "/class.html, " << args_.out << "/feedback/, " << args_.out << "/students/\n";
}

}  // namespace

int runClassGrade(const ClassGradeArgs& args) {
    return ClassGrading(args).run();
}

}  // namespace sl
