// What the window may draw, and what it tries next. Each stage of each tree has a record: the
// fingerprint of its files (its own folder and the shared common/ and phong/, in our tree and
// the student's folder) with a verdict, and the parameter values its programs drew with in
// the worker. A settled save makes only the stages whose files changed pending; a pending
// stage, and values on screen that its programs have not drawn with yet, are tried in the
// bounded worker one job at a time (the picture on screen first); nothing pending waits
// without a job running or queued, and every job ends (window/trial_runner.h).
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "window/shader_watch.h"
#include "window/trial_runner.h"

namespace sl {

class Watchdog {
  public:
    using Clock = std::chrono::steady_clock;
    // Where the files are: our two trees, the student's folder and the tree it is written for.
    struct Folders {
        std::string core, legacy, overlay;
        GlslTree overlayTree = GlslTree::Core;
    };
    Watchdog(const Folders& folders, const BudgetRule& rule, Backend backend);

    // What happened, for the window to act on (drained by events()).
    struct Event {
        enum class Kind { Adopt, AdoptShared, Refused, Lost, ValueRefused } kind;
        GlslTree tree;
        std::string stage;
        Sets sets;           // ValueRefused: the values
        std::string what;    // Refused, Lost, ValueRefused: why
        bool first = false;  // the first verdict on the student's files (at the start)
    };

    // The picture on screen: its stage and tree, and the values in use (those on screen first,
    // then the split view's halves), each as the values off their defaults.
    struct OnScreen {
        GlslTree tree = GlslTree::Core;
        std::string stage, scene;
        std::vector<Sets> sets;
    };
    // Called a few times a second: notices settled saves, collects the running job's verdict,
    // starts the next job. `sessionTree`: the trees whose changed stages are tried in the
    // background (the other tree waits until it is switched to). `jobFor` gives a stage's
    // scene and values as the window has them. `width` x `height`: the window's size.
    void tick(Clock::time_point now, const OnScreen& screen, GlslTree sessionTree,
              const std::function<TrialJob(GlslTree, const std::string&)>& jobFor, int width,
              int height);
    // `r`: the files on disk now (settled or not), the stage on screen tried again whatever its
    // verdict, values and losses forgotten.
    void retry(const OnScreen& screen);
    std::vector<Event> events();

    // Queries for drawing.
    std::string key(GlslTree tree, const std::string& stage) const;
    bool adopted(GlslTree tree, const std::string& stage) const;  // a good version was adopted
    // The files on disk are the ones that drew (a program built from them now is safe).
    bool diskIsGood(GlslTree tree, const std::string& stage) const;
    bool filesPending(GlslTree tree, const std::string& stage) const;
    std::string refused(GlslTree tree, const std::string& stage) const;  // "" if not
    std::string lost(GlslTree tree, const std::string& stage) const;     // "" if not
    // The values to draw with for `sets`: themselves once they drew, else the last that drew.
    Sets drawable(GlslTree tree, const std::string& stage, const Sets& sets) const;
    bool valuePending(GlslTree tree, const std::string& stage, const Sets& sets) const;
    std::string valueRefused(GlslTree tree, const std::string& stage, const Sets& sets) const;
    // Something of these trees still waits for a trial (scripted runs wait for it).
    bool busy(const OnScreen& screen, GlslTree sessionTree) const;
    bool running() const { return runner_.running(); }
    const TrialRunner& runner() const { return runner_; }

    // The jobs tried so far, the last ones (for --state).
    struct Tried {
        std::string tree, stage, what;  // what: "files" | "values"
        Sets sets;
        std::string verdict;  // "drew" | "refused" | "lost" | "running" | "superseded"
        double cpuSeconds = 0, budgetSeconds = 0, oursSeconds = -1;
        double startedAt = 0, endedAt = 0;  // steady clock, seconds
    };
    const std::vector<Tried>& tried() const { return tried_; }
    int triedCount() const { return triedCount_; }

  private:
    struct Record {
        std::uint64_t onDisk = 0;   // the stage's files as last settled
        std::uint64_t decided = 0;  // the files the verdict is about
        bool hasVerdict = false;
        std::string refused;       // why `decided` did not draw ("" = it drew)
        std::string lost;          // a trial of `onDisk` lost its worker (not tried again
        std::uint64_t lostAt = 0;  // automatically until the files change or `r`)
        bool student = false;      // the student's files take part, or ours were edited
        bool adopted = false;      // the window holds a good version of the programs
        bool firstTry = true;      // nothing of the student's files tried yet
        ShaderWatch::Files decidedFiles;
        std::set<Sets> good;
        std::map<Sets, std::string> bad;
        Sets lastGood;
    };
    struct Job {
        bool values = false;
        GlslTree tree;
        std::string stage;
        std::uint64_t files = 0;
        Sets sets;
    };
    bool relevant(const std::string& path, GlslTree tree, const std::string& stage) const;
    ShaderWatch::Files filesOf(GlslTree tree, const std::string& stage) const;
    std::uint64_t fingerprint(GlslTree tree, const std::string& stage) const;
    void refresh();  // every record's onDisk from the watch
    const Record* find(GlslTree tree, const std::string& stage) const;
    bool needsFiles(const Record& r) const;
    void finish(const TrialVerdict& verdict, Clock::time_point now);
    void startJob(const Job& job, const TrialJob& trial, Clock::time_point now);
    std::string withFiles(const std::string& why, const Record& r, GlslTree tree,
                          const std::string& stage) const;

    Folders folders_;
    ShaderWatch watch_;
    TrialRunner runner_;
    std::map<std::string, Record> records_;  // by key()
    std::map<GlslTree, std::uint64_t> sharedAdopted_;
    Job job_;
    std::vector<Event> events_;
    std::vector<Tried> tried_;
    int triedCount_ = 0;
};

}  // namespace sl
