#include "course/class_grade.h"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
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
#include <thread>

#include "course/class_annotations.h"
#include "course/class_entries.h"
#include "course/class_page.h"
#include "course/class_progress.h"
#include "course/feedback_html.h"
#include "course/gradebook_exports.h"
#include "course/intake_adapter.h"
#include "course/roster.h"
#include "course/solution_check.h"
#include "course/student_grade.h"
#include "grade/check_run.h"  // drawSeed
#include "io/box.h"
#include "io/content_hash.h"
#include "io/files.h"
#include "io/usage_error.h"
#include "sandbox/private_dir.h"
#include "sandbox/worker.h"
#include "stages/displaced_bounds.h"
#include "stages/expectations.h"

namespace sl {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// A job that could not write for want of space exits with this (its log may be lost with it).
constexpr int kJobDiskFull = 4;

// A write the disk had no room for is the machine's failure (exit 3), in one line: records and
// outputs are written atomically, so whatever an earlier run wrote is still whole.
[[noreturn]] void throwWriteError(const std::string& err) {
    if (diskFull(errno))
        throw DiskFullError("grade: the disk is full: " + err +
                            " (what earlier runs wrote is kept): free space and rerun grade");
    throw UsageError("grade: " + err);
}

void writeOrThrow(const std::string& path, const std::string& text) {
    std::string err = writeFileAtomically(path, text.data(), text.size());
    if (!err.empty()) throwWriteError(err);
}

// A record as kept in OUT/students/: its JSON with "record_hash", the FNV-1a of the rest of it
// (compact, keys sorted), so a record changed since it was written (a score raised by hand) is
// told from one grade wrote. A change detector, not a signature: anyone may recompute it.
std::string sealedRecordText(const StudentRecord& r) {
    json j = recordJson(r);
    j["record_hash"] = fnv1aHex(j.dump(-1, ' ', false, json::error_handler_t::replace));
    return j.dump(1, ' ', false, json::error_handler_t::replace) + "\n";
}

// The record kept at `path` for the student named exactly `student`, if it can be read as one
// and its content hash matches; `changed` (when given) is set when it was edited since.
std::optional<StudentRecord> keptRecord(const std::string& path, const std::string& student,
                                        bool* changed = nullptr) {
    std::string text;
    if (!readRegularFile(path, 64u << 20, text, true).empty()) return std::nullopt;
    try {
        json j = json::parse(text);
        const std::string hash = j.value("record_hash", "");
        j.erase("record_hash");
        StudentRecord r = recordFromJson(j);
        if (r.student != student) return std::nullopt;  // another name's record: not theirs
        if (hash != fnv1aHex(j.dump(-1, ' ', false, json::error_handler_t::replace))) {
            if (changed) *changed = true;  // edited by hand, or written before records had one
            return std::nullopt;
        }
        return r;
    } catch (const std::exception&) {  // malformed, an older version, a lesson since renamed
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
// none, else why it is set aside.
std::string whyGrade(const std::optional<StudentRecord>& kept, const std::string& handIn,
                     const std::string& assignment, std::uint64_t seed, bool asked) {
    if (asked) return "asked for (--regrade)";
    if (!kept) return "new";
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

// grade's own names directly under --out and inside its own folders: a symbolic link at any of
// them would have every log, page and record written (or a job's log truncated) wherever it
// points, so one refuses the run before anything is written (exit 2). Nothing is followed.
void refuseLinksInOut(const std::string& out) {
    auto refuse = [](const std::string& path) {
        throw UsageError("--out: " + printableName(path) +
                         " is a symbolic link: grade writes nothing through a link (remove it)");
    };
    struct stat st;
    if (::stat(out.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
        return;  // --out itself may be a link
    for (const char* name :
         {".grade.lock", "solution_check.txt", "grades.csv", "gradebook-canvas.csv",
          "gradebook-moodle.csv", "class.html", "adjustments.csv"})
        if (::lstat((out + "/" + name).c_str(), &st) == 0 && S_ISLNK(st.st_mode))
            refuse(out + "/" + name);
    for (const char* name : {"students", "feedback", "work", "logs"}) {
        const std::string folder = out + "/" + name;
        if (::lstat(folder.c_str(), &st) != 0) continue;
        if (S_ISLNK(st.st_mode)) refuse(folder);
        if (!S_ISDIR(st.st_mode))
            throw UsageError("--out: " + printableName(folder) + " is not a folder");
        DIR* dir = ::opendir(folder.c_str());
        if (!dir) throw UsageError("--out: cannot list " + printableName(folder));
        std::string link;
        while (const dirent* e = ::readdir(dir)) {
            const std::string path = folder + "/" + e->d_name;
            if (link.empty() && ::lstat(path.c_str(), &st) == 0 && S_ISLNK(st.st_mode)) link = path;
        }
        ::closedir(dir);
        if (!link.empty()) refuse(link);
    }
}

// One grade run per --out at a time: an flock held by the run's own process until it ends (its
// jobs let go of their copy, so a killed run frees --out at once), the holder's pid written in
// the lock file for the refusal to name.
class OutLock {
  public:
    explicit OutLock(const std::string& out) {
        std::string path = out + "/.grade.lock";
        fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644);
        if (fd_ < 0) throw UsageError("--out: cannot write " + printableName(path));
        if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
            char pid[32] = {};
            ssize_t n = ::pread(fd_, pid, sizeof pid - 1, 0);
            ::close(fd_);
            std::string holder = n > 0 ? std::string(pid, std::size_t(n)) : "?";
            holder.erase(holder.find_last_not_of(" \n") + 1);
            throw UsageError("--out: " + printableName(out) +
                             " is in use by another grade run (pid " + printable(holder) +
                             "): wait for it to end or give another --out");
        }
        // The pid is only for another run's message; the lock itself is the flock.
        std::string pid = std::to_string(::getpid()) + "\n";
        if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, pid.data(), pid.size(), 0) < 0)
            pid.clear();  // no pid to name: the lock holds all the same
    }
    ~OutLock() { ::close(fd_); }
    void closeInJob() {  // in a forked job: the lock stays the parent's alone
        ::close(fd_);
        fd_ = -1;
    }
    OutLock(const OutLock&) = delete;
    OutLock& operator=(const OutLock&) = delete;

  private:
    int fd_ = -1;
};

std::string duration(double s) {
    char t[32];
    if (s >= 90)
        std::snprintf(t, sizeof t, "%d min %02d s", int(s) / 60, int(s) % 60);
    else
        std::snprintf(t, sizeof t, "%.0f s", s);
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

// The roster's students with no hand-in get a record and a page ("no hand-in", every stage
// MISSING) so the gradebook is complete; hand-ins the roster does not list are named.
void addRosterStudents(const Roster& roster, const Assignment& a,
                       const std::vector<std::string>& names, const std::string& out,
                       std::vector<StudentRecord>& records, std::vector<std::string>& pages) {
    for (const RosterEntry* e : rosterWithoutHandIn(roster, names)) {
        records.push_back(noHandInRecord(a, *e));
        pages.push_back("feedback/" + recordKey(e->handIn) + ".html");
        writeOrThrow(out + "/" + pages.back(), studentPage(records.back()));
    }
    std::vector<std::string> strangers = handInsNotOnRoster(roster, names);
    if (strangers.empty()) return;
    std::cout << strangers.size() << " hand-in" << (strangers.size() == 1 ? "" : "s")
              << " not on the roster:";
    for (const std::string& n : strangers) std::cout << " " << printableName(n);
    std::cout << "\n";
}

}  // namespace

int runClassGrade(const ClassGradeArgs& args) {
    if (args.jobs < 0 || args.jobs > 64) throw UsageError("--jobs: give 1 to 64, or auto");
    Assignment a = loadAssignment(args.assignment);
    std::string assignmentText;
    readRegularFile(args.assignment, 1u << 20, assignmentText);
    // A record stands on a rerun only for the same assignment text and the same hand-in.
    const std::string assignmentHash = fnv1aHex(assignmentText);
    struct stat st;
    if (::stat(args.submissions.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
        throw UsageError(
            "grade: " + printableName(args.submissions) +
            " is not a folder (give the folder holding one folder or .zip per student)");
    refuseOverlap(args.submissions, args.out);
    refuseLinksInOut(args.out);
    const ClassListing listing = listClass(args.submissions);
    if (listing.handIns.empty())
        throw UsageError(
            "grade: " + printableName(args.submissions) + " holds no submission" +
            (listing.skipped.empty() ? "" : " (left out: " + skippedList(listing) + ")"));
    GradeSettings settings = args.settings;
    {
        std::vector<std::string> kept, students;
        for (const ClassEntry& e : listing.handIns) {
            kept.push_back(args.out + "/students/" + e.key + ".json");
            students.push_back(e.student);
        }
        settings.seed = classSeed(args, kept, students);
    }
    // Mesa's shader cache, one for the whole run (the solution check, every job, every worker):
    // our shipped programs are compiled once per class instead of once per student, lesson and
    // view, and a student's own once per student. Keyed by the shader's text and the driver, so
    // no hand-in is served another's program; private, gone with the run.
    PrivateDir shaderCache("shadowlab-shader-cache");
    useShaderCacheFolder(shaderCache.path());
    SolutionTrees trees = solutionTrees(args.solutions);
    const std::string checkKey = solutionCheckKey(assignmentHash, trees, *settings.seed);
    const bool checked = solutionCheckPassed(args.out, checkKey);
    if (checked) {
        std::cout << "the solution (" << trees.describe() << ") passed "
                  << printableName(args.assignment) << " in an earlier run: not graded again\n";
    } else {
        std::cout << "grading the solution (" << trees.describe() << ") by "
                  << printableName(args.assignment) << " first\n"
                  << std::flush;
        verifySolution(a, trees, settings);
    }
    std::error_code mkdirError;
    fs::create_directories(args.out, mkdirError);
    refuseLinksInOut(args.out);  // again: the solution check took a while
    OutLock lock(args.out);
    for (const char* sub : {"/students", "/feedback", "/work", "/logs"}) {
        // mkdir, never through a link: one planted since the check above is refused here.
        struct stat made;
        if (::mkdir((args.out + sub).c_str(), 0755) != 0 && errno != EEXIST)
            throw UsageError("--out: cannot create " + printableName(args.out + sub));
        if (::lstat((args.out + sub).c_str(), &made) != 0 || !S_ISDIR(made.st_mode))
            throw UsageError("--out: " + printableName(args.out + sub) +
                             " is not a folder (a symbolic link is refused: remove it)");
    }
    if (!checked) {
        std::string line = checkKey + "\n";
        std::string err =
            writeFileAtomically(args.out + "/solution_check.txt", line.data(), line.size());
        if (!err.empty() && diskFull(errno)) throwWriteError(err);
        if (!err.empty()) throw std::runtime_error("grade: " + err);
    }
    std::vector<std::string> entries, names, files, refusals;
    for (const ClassEntry& e : listing.handIns) {
        entries.push_back(e.path);
        names.push_back(e.student);
        files.push_back(e.key);
        refusals.push_back(e.refusal);
    }
    // The roster, --times and the adjustments: read (and refused, exit 2) before any work.
    ClassAnnotations annotations = readAnnotations(args, a, names);
    warnOnDownloadTimes(annotations, a, names, entries);
    for (const std::string& wanted : args.regrade)
        if (std::find(names.begin(), names.end(), wanted) == names.end())
            throw UsageError("--regrade: no hand-in named '" + printableName(wanted) + "' in " +
                             printableName(args.submissions));
    auto recordPath = [&](std::size_t k) { return args.out + "/students/" + files[k] + ".json"; };
    const std::size_t n = entries.size();
    std::vector<std::string> hashes(n);
    std::vector<std::size_t> todo;
    std::map<std::string, int> reasons;  // why students are graded in this run
    for (std::size_t k = 0; k < n; ++k) {
        hashes[k] = handInHash(entries[k]);
        bool asked = args.regradeAll || std::find(args.regrade.begin(), args.regrade.end(),
                                                  names[k]) != args.regrade.end();
        bool edited = false;
        std::optional<StudentRecord> kept = keptRecord(recordPath(k), names[k], &edited);
        std::string why = whyGrade(kept, hashes[k], assignmentHash, *settings.seed, asked);
        if (edited && !asked) why = "its record does not match its content hash (edited?)";
        if (why.empty()) continue;
        todo.push_back(k);
        ++reasons[why];
        if (why != "new")
            std::cout << "grading " << printableName(escapedName(names[k])) << " again: " << why
                      << "\n";
    }
    std::cout << "grade " << n << " submissions by " << printableName(args.assignment) << " ("
              << a.name << ")";
    if (todo.size() < n || reasons.count("new") < reasons.size()) {
        std::cout << ": " << n - todo.size() << " already graded, " << todo.size() << " to grade";
        std::string why;
        for (const auto& [reason, count] : reasons)
            why += (why.empty() ? " (" : ", ") + std::to_string(count) + " " + reason;
        if (!why.empty()) std::cout << why << ")";
    }
    std::cout << "\n";
    if (!listing.skipped.empty())
        std::cout << "left out, not hand-ins: " << skippedList(listing) << "\n";
    std::cout << std::flush;

    // Intake in the parent (no GL here): every pending submission's snapshot.
    std::vector<StudentWork> subs(n);
    for (std::size_t k : todo) {
        if (refusals[k].empty()) {
            subs[k] = intakeForAssignment(a, entries[k], args.out + "/work/" + files[k]);
        } else {
            subs[k] = StudentWork();
            subs[k].error = refusals[k];  // nothing of it is read, followed or copied
        }
        subs[k].name = names[k];
        subs[k].hash = hashes[k];
        std::error_code ec;
        fs::create_directories(args.out + "/work/" + files[k] + "/images", ec);
    }
    settings.pictures = true;
    settings.pagePicturesOnly = true;
    std::map<std::string, std::string> imageDirs;
    for (std::size_t k : todo) imageDirs[subs[k].name] = args.out + "/work/" + files[k] + "/images";
    settings.imageDir = [imageDirs](const StudentWork& s) {
        auto it = imageDirs.find(s.name);
        return it == imageDirs.end() ? std::string() : it->second;
    };

    // Jobs: child processes, each grading every jobs-th pending student in one worker series
    // with one calibration of our shaders, on its share of the cores (a worker with llvmpipe's
    // and the figures' threads on every core, twice over, was slower than one job: issue 28).
    const int cores = boxCores();
    const int wanted = args.jobs > 0 ? args.jobs : boxJobs(kMbPerGradingJob);
    int jobs =
        int(std::min<std::size_t>(std::size_t(wanted), std::max<std::size_t>(todo.size(), 1)));
    const int coresPerJob = std::max(1, cores / std::max(1, jobs));
    auto progressPath = [&](int j) {
        return args.out + "/logs/job-" + std::to_string(j) + ".progress";
    };
    if (!todo.empty())
        std::cout << jobs << (jobs == 1 ? " job" : " jobs") << " on " << cores
                  << (cores == 1 ? " core" : " cores")
                  << (args.jobs > 0 ? " (--jobs)" : " (--jobs auto)") << "\n";
    std::vector<pid_t> pids;
    std::cout.flush();
    std::cerr.flush();
    for (int j = 0; j < jobs && !todo.empty(); ++j) {
        pid_t pid = ::fork();
        if (pid < 0) throw std::runtime_error("grade: cannot start a job process");
        if (pid == 0) {
            ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // a killed grade leaves no job behind
            lock.closeInJob();
            shareCores(coresPerJob);
            std::string log = args.out + "/logs/job-" + std::to_string(j) + ".log";
            // O_NOFOLLOW: a link planted at the log's name is never truncated through.
            int fd =
                ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0644);
            // Its students get no record: named, not graded, exit 3.
            if (fd < 0) ::_exit(diskFull(errno) ? kJobDiskFull : 3);
            if (fd >= 0) {
                ::dup2(fd, 1);
                ::dup2(fd, 2);
                ::close(fd);
            }
            int code = 0;
            try {
                std::vector<StudentWork> share;
                std::vector<GradingPlan> plans;
                std::vector<std::size_t> index;
                for (std::size_t i = std::size_t(j); i < todo.size(); i += std::size_t(jobs)) {
                    share.push_back(subs[todo[i]]);
                    plans.push_back(planStudent(a, share.back(), settings.seed));
                    index.push_back(todo[i]);
                }
                Calibration calibration(settings.budget, settings.backend);
                JobProgress progress(progressPath(j), plans);
                gradeStudents(
                    plans, share, settings, calibration,
                    [&](std::size_t i, const StageRecord& st) { progress.stageDone(plans[i], st); },
                    [&](std::size_t i, StudentRecord r) {
                        r.assignmentHash = assignmentHash;
                        writeOrThrow(recordPath(index[i]), sealedRecordText(r));
                    });
            } catch (const DiskFullError& e) {
                std::cerr << "shadowlab: grade job " << j << ": " << e.what() << "\n";
                code = kJobDiskFull;
            } catch (const std::exception& e) {
                std::cerr << "shadowlab: grade job " << j << ": " << e.what() << "\n";
                code = 3;
            }
            std::cout.flush();
            std::cerr.flush();
            ::_exit(code);
        }
        pids.push_back(pid);
    }
    // Progress: a line each time a student is done, with the time left at the pace of the
    // rows the jobs rendered (course/class_progress.h).
    auto start = std::chrono::steady_clock::now();
    std::set<std::size_t> reported;
    std::vector<std::string> progressFiles;
    for (int j = 0; j < jobs; ++j) progressFiles.push_back(progressPath(j));
    Pace pace;
    int exitCode = 0, diskFullJobs = 0;
    std::size_t running = pids.size();
    auto isFresh = [&](std::size_t k, std::optional<StudentRecord>& r) {
        r = keptRecord(recordPath(k), names[k]);
        return r && r->handInHash == hashes[k] && r->assignmentHash == assignmentHash;
    };
    auto poll = [&]() {
        // Read every time, so the pace starts from the first rows that came back.
        const double now =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const std::optional<double> rowsLeft = pace.timeLeft(now, readProgress(progressFiles));
        for (std::size_t k : todo) {
            if (reported.count(k)) continue;
            std::optional<StudentRecord> r;
            if (!isFresh(k, r)) continue;
            reported.insert(k);
            annotateRecord(annotations, a, names[k], entries[k], *r);  // the total, as pages show
            double left =
                rowsLeft ? *rowsLeft
                         : now / double(reported.size()) * double(todo.size() - reported.size());
            char line[512];
            std::snprintf(line, sizeof line,
                          "[student %zu of %zu] %-24s %7.2f / %.2f  %-10s time left about %s\n",
                          n - todo.size() + reported.size(), n,
                          printableName(escapedName(names[k])).c_str(),
                          r->graded() ? r->total() : r->score, r->maxScore, statusName(r->status()),
                          reported.size() == todo.size() ? "0 s" : duration(left).c_str());
            std::cout << line << std::flush;
        }
    };
    while (running > 0) {
        int status = 0;
        pid_t done = ::waitpid(-1, &status, WNOHANG);
        if (done > 0 && std::find(pids.begin(), pids.end(), done) != pids.end()) {
            --running;
            if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) exitCode = 3;
            if (WIFEXITED(status) && WEXITSTATUS(status) == kJobDiskFull) ++diskFullJobs;
        } else if (done <= 0) {
            std::this_thread::sleep_for(std::chrono::milliseconds(300));
        }
        poll();
    }
    poll();
    if (diskFullJobs > 0) {  // one line, not one a student: the outputs would not fit either
        std::size_t lost = todo.size() - reported.size();
        throw DiskFullError("grade: the disk under " + printableName(args.out) + " is full: " +
                            std::to_string(lost) + " of " + std::to_string(todo.size()) +
                            " students' records could not be written (not graded; what earlier "
                            "runs wrote is kept): free space and rerun grade");
    }

    // The class's outputs from every record (those of earlier runs too).
    addCopyFlags(annotations, a, names, files, args.out, trees);
    std::vector<StudentRecord> records;
    std::vector<std::string> pages;
    std::size_t notGraded = 0;
    for (std::size_t k = 0; k < n; ++k) {
        std::optional<StudentRecord> r;
        if (!isFresh(k, r)) {
            std::cerr << "shadowlab: " << printableName(escapedName(names[k]))
                      << ": no record (its job failed; see " << args.out
                      << "/logs/): not graded, rerun grade\n";
            ++notGraded;
            continue;
        }
        if (!r->graded()) ++notGraded;
        if (annotateRecord(annotations, a, names[k], entries[k], *r))
            writeOrThrow(recordPath(k), sealedRecordText(*r));
        records.push_back(*r);
        pages.push_back("feedback/" + files[k] + ".html");
        writeOrThrow(args.out + "/" + pages.back(), studentPage(*r));
    }
    if (annotations.roster)
        addRosterStudents(*annotations.roster, a, names, args.out, records, pages);
    writeOrThrow(args.out + "/grades.csv", gradesCsv(records));
    writeOrThrow(args.out + "/gradebook-canvas.csv", canvasCsv(a.name, records));
    writeOrThrow(args.out + "/gradebook-moodle.csv", moodleCsv(a.name, records));
    writeOrThrow(args.out + "/class.html",
                 classPage(a.name, records, pages, listing.skipped,
                           {annotations.pairs, annotations.solutionCopies}));
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::size_t copyFull = 0;  // hand-ins whose private copy found the disk full (NOT GRADED)
    for (std::size_t k : todo) copyFull += subs[k].platformFailure;
    if (copyFull > 0)
        std::cerr << "shadowlab: grade: the disk was full: " << copyFull
                  << (copyFull == 1 ? " hand-in" : " hand-ins")
                  << " could not be copied to be graded (NOT GRADED, not the students' fault): "
                     "free space and rerun grade\n";
    std::cout << "graded " << n - notGraded << " of " << n;
    if (notGraded > 0) std::cout << "; " << notGraded << " not graded: rerun";
    std::cout << " in " << duration(seconds) << ": " << args.out << "/grades.csv, " << args.out
              << "/class.html, " << args.out << "/feedback/, " << args.out << "/students/\n";
    if (notGraded > 0) exitCode = 3;
    return exitCode;
}

}  // namespace sl
