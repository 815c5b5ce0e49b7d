#include "window/watchdog.h"

#include <algorithm>

#include "render/stage_interface.h"
#include "stages/registry.h"

namespace sl {

namespace {

// Folders every stage's programs read: the shared include and the map view's program
// (common/), the light view's (phong/). (hud/ is not: the window's text is always drawn with
// ours.)
bool sharedFolder(const std::string& folder) {
    return folder == "common" || folder == lightingStage().id;
}

double secondsOf(Watchdog::Clock::time_point t) {
    return std::chrono::duration<double>(t.time_since_epoch()).count();
}

constexpr std::size_t kTriedKept = 24;

}  // namespace

Watchdog::Watchdog(const Folders& folders, const BudgetRule& rule, Backend backend)
    : folders_(folders),
      watch_({folders.core, folders.legacy, folders.overlay}),
      runner_(rule, backend) {
    // Ours as shipped are trusted; a stage the student's folder takes part in is tried first.
    for (GlslTree tree : {GlslTree::Core, GlslTree::Legacy})
        for (const StageInfo& s : stageRegistry()) {
            if (s.legacyOnly && tree == GlslTree::Core) continue;
            Record& r = records_[key(tree, s.id)];
            r.onDisk = fingerprint(tree, s.id);
            for (const auto& [path, stamp] : filesOf(tree, s.id))
                if (!folders_.overlay.empty() && path.rfind(folders_.overlay + "/", 0) == 0)
                    r.student = true;
            if (!r.student) {
                r.hasVerdict = r.adopted = true;
                r.decided = r.onDisk;
                r.decidedFiles = filesOf(tree, s.id);
                r.firstTry = false;
            }
        }
    for (GlslTree tree : {GlslTree::Core, GlslTree::Legacy}) sharedAdopted_[tree] = 0;
}

std::string Watchdog::key(GlslTree tree, const std::string& stage) const {
    return std::string(treeName(tree)) + "/" + stage;
}

bool Watchdog::relevant(const std::string& path, GlslTree tree, const std::string& stage) const {
    std::string rest;
    const std::string& root = tree == GlslTree::Core ? folders_.core : folders_.legacy;
    if (path.rfind(root + "/", 0) == 0)
        rest = path.substr(root.size() + 1);
    else if (!folders_.overlay.empty() && tree == folders_.overlayTree &&
             path.rfind(folders_.overlay + "/", 0) == 0)
        rest = path.substr(folders_.overlay.size() + 1);
    else
        return false;
    const std::string folder = rest.substr(0, rest.find('/'));
    return rest.find('/') != std::string::npos && (folder == stage || sharedFolder(folder));
}

ShaderWatch::Files Watchdog::filesOf(GlslTree tree, const std::string& stage) const {
    ShaderWatch::Files files;
    for (const auto& [path, stamp] : watch_.settled())
        if (relevant(path, tree, stage)) files.emplace(path, stamp);
    return files;
}

std::uint64_t Watchdog::fingerprint(GlslTree tree, const std::string& stage) const {
    std::uint64_t h = 14695981039346656037ULL;
    auto mix = [&h](const void* data, std::size_t n) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 1099511628211ULL;
    };
    for (const auto& [path, stamp] : filesOf(tree, stage)) {
        mix(path.data(), path.size());
        mix(&stamp, sizeof stamp);
    }
    return h;
}

void Watchdog::refresh() {
    for (GlslTree tree : {GlslTree::Core, GlslTree::Legacy})
        for (const StageInfo& s : stageRegistry()) {
            auto it = records_.find(key(tree, s.id));
            if (it == records_.end()) continue;
            Record& r = it->second;
            r.onDisk = fingerprint(tree, s.id);
            if (r.onDisk != r.decided && !r.student) r.student = true;  // ours were edited
        }
}

const Watchdog::Record* Watchdog::find(GlslTree tree, const std::string& stage) const {
    auto it = records_.find(key(tree, stage));
    return it == records_.end() ? nullptr : &it->second;
}

bool Watchdog::needsFiles(const Record& r) const {
    const bool changed = !r.hasVerdict || r.onDisk != r.decided;
    return changed && !(!r.lost.empty() && r.lostAt == r.onDisk);
}

bool Watchdog::adopted(GlslTree tree, const std::string& stage) const {
    const Record* r = find(tree, stage);
    return r && r->adopted;
}
bool Watchdog::diskIsGood(GlslTree tree, const std::string& stage) const {
    const Record* r = find(tree, stage);
    return r && r->hasVerdict && r->decided == r->onDisk && r->refused.empty();
}
bool Watchdog::filesPending(GlslTree tree, const std::string& stage) const {
    const Record* r = find(tree, stage);
    return r && needsFiles(*r);
}
std::string Watchdog::refused(GlslTree tree, const std::string& stage) const {
    const Record* r = find(tree, stage);
    return r && r->hasVerdict ? r->refused : "";
}
std::string Watchdog::lost(GlslTree tree, const std::string& stage) const {
    const Record* r = find(tree, stage);
    return r ? r->lost : "";
}

Sets Watchdog::drawable(GlslTree tree, const std::string& stage, const Sets& sets) const {
    const Record* r = find(tree, stage);
    if (!r || !r->student || r->good.count(sets)) return sets;
    return r->lastGood;
}

bool Watchdog::valuePending(GlslTree tree, const std::string& stage, const Sets& sets) const {
    const Record* r = find(tree, stage);
    return r && r->student && r->adopted && !r->good.count(sets) && !r->bad.count(sets);
}

std::string Watchdog::valueRefused(GlslTree tree, const std::string& stage,
                                   const Sets& sets) const {
    const Record* r = find(tree, stage);
    if (!r || !r->student || r->good.count(sets)) return "";
    auto bad = r->bad.find(sets);
    return bad == r->bad.end() ? "" : bad->second;
}

bool Watchdog::busy(const OnScreen& screen, GlslTree sessionTree) const {
    if (runner_.running() || watch_.pending()) return true;
    for (const auto& [k, r] : records_) {
        const bool inTree = k.rfind(std::string(treeName(sessionTree)) + "/", 0) == 0 ||
                            k == key(screen.tree, screen.stage);
        if (inTree && needsFiles(r)) return true;
    }
    for (const Sets& sets : screen.sets)
        if (valuePending(screen.tree, screen.stage, sets)) return true;
    return false;
}

std::vector<Watchdog::Event> Watchdog::events() {
    std::vector<Event> out;
    out.swap(events_);
    return out;
}

void Watchdog::retry(const OnScreen& screen) {
    runner_.abandon();
    watch_.settleNow();
    refresh();
    for (auto& [k, r] : records_) {
        r.lost.clear();
        r.bad.clear();
    }
    auto it = records_.find(key(screen.tree, screen.stage));
    if (it != records_.end()) it->second.hasVerdict = false;
}

void Watchdog::startJob(const Job& job, const TrialJob& trial, Clock::time_point now) {
    job_ = job;
    runner_.start(trial);
    Tried t{treeName(job.tree), job.stage, job.values ? "values" : "files", job.sets, "running"};
    t.budgetSeconds = runner_.budgetSeconds();
    t.startedAt = secondsOf(now);
    tried_.push_back(t);
    if (tried_.size() > kTriedKept) tried_.erase(tried_.begin());
    ++triedCount_;
}

std::string Watchdog::withFiles(const std::string& why, const Record& r, GlslTree tree,
                                const std::string& stage) const {
    // A loop or a crash has no file in its message: name the files it is about, the ones
    // changed since the last verdict (all the student's at the first).
    std::vector<std::string> named;
    for (const auto& [path, stamp] : filesOf(tree, stage)) {
        auto before = r.decidedFiles.find(path);
        const bool changed = before == r.decidedFiles.end() || before->second != stamp;
        const bool students =
            !folders_.overlay.empty() && path.rfind(folders_.overlay + "/", 0) == 0;
        if ((r.firstTry && students) || (!r.firstTry && changed)) named.push_back(path);
    }
    for (const auto& [path, stamp] : r.decidedFiles)  // removed since (ours takes over)
        if (!r.firstTry && !filesOf(tree, stage).count(path)) named.push_back(path + " (removed)");
    for (const auto& n : named)
        if (why.find(n) != std::string::npos) return why;  // it names its file
    if (named.empty()) return why;
    std::string list;
    for (std::size_t k = 0; k < named.size() && k < 3; ++k)
        list += (list.empty() ? "" : ", ") + named[k];
    if (named.size() > 3) list += " and " + std::to_string(named.size() - 3) + " more";
    return list + (r.firstTry ? "" : named.size() == 1 ? " (changed)" : " (changed)") + ": " + why;
}

void Watchdog::finish(const TrialVerdict& v, Clock::time_point now) {
    Tried& t = tried_.back();
    t.endedAt = secondsOf(now);
    t.cpuSeconds = v.cpuSeconds;
    t.budgetSeconds = v.budgetSeconds;
    t.oursSeconds = v.oursSeconds;
    t.verdict = v.kind == TrialVerdict::Kind::Drew      ? "drew"
                : v.kind == TrialVerdict::Kind::Refused ? "refused"
                                                        : "lost";
    auto it = records_.find(key(job_.tree, job_.stage));
    if (it == records_.end()) return;
    Record& r = it->second;
    if (r.onDisk != job_.files) {  // saved again meanwhile: the next job decides
        t.verdict = "superseded";
        return;
    }
    if (job_.values) {
        if (v.kind == TrialVerdict::Kind::Drew) {
            r.good.insert(job_.sets);
            return;
        }
        r.bad[job_.sets] = v.what;
        events_.push_back({Event::Kind::ValueRefused, job_.tree, job_.stage, job_.sets, v.what});
        return;
    }
    if (v.kind == TrialVerdict::Kind::Lost) {
        r.lost = v.what;
        r.lostAt = r.onDisk;
        events_.push_back({Event::Kind::Lost, job_.tree, job_.stage, {}, v.what});
        return;
    }
    const std::string why = v.kind == TrialVerdict::Kind::Refused
                                ? withFiles(v.what, r, job_.tree, job_.stage)
                                : std::string();
    const bool first = r.firstTry;
    r.hasVerdict = true;
    r.decided = r.onDisk;
    r.decidedFiles = filesOf(job_.tree, job_.stage);
    r.lost.clear();
    r.firstTry = false;
    r.refused = why;
    if (v.kind == TrialVerdict::Kind::Refused) {
        events_.push_back({Event::Kind::Refused, job_.tree, job_.stage, {}, why, first});
        return;
    }
    r.adopted = true;
    r.good = {job_.sets};
    r.bad.clear();
    r.lastGood = job_.sets;
    events_.push_back({Event::Kind::Adopt, job_.tree, job_.stage, {}, "", first});
    // The shared folders' programs once every stage of the tree drew with these files.
    std::uint64_t shared = 14695981039346656037ULL;
    for (const auto& [path, stamp] : watch_.settled())
        if (relevant(path, job_.tree, "")) shared = (shared ^ stamp) * 1099511628211ULL;
    bool all = true;
    for (const auto& [k, other] : records_)
        if (k.rfind(std::string(treeName(job_.tree)) + "/", 0) == 0)
            all = all && other.hasVerdict && other.decided == other.onDisk && other.refused.empty();
    if (all && sharedAdopted_[job_.tree] != shared) {
        sharedAdopted_[job_.tree] = shared;
        events_.push_back({Event::Kind::AdoptShared, job_.tree, "", {}, ""});
    }
}

void Watchdog::tick(Clock::time_point now, const OnScreen& screen, GlslTree sessionTree,
                    const std::function<TrialJob(GlslTree, const std::string&)>& jobFor, int width,
                    int height) {
    if (watch_.poll(now)) {
        refresh();
        // A running job about files that changed again is of no use any more.
        auto it = records_.find(key(job_.tree, job_.stage));
        if (runner_.running() && it != records_.end() && it->second.onDisk != job_.files) {
            runner_.abandon();
            tried_.back().verdict = "superseded";
            tried_.back().endedAt = secondsOf(now);
        }
    }
    TrialVerdict verdict;
    if (runner_.running() && runner_.poll(verdict)) finish(verdict, now);
    if (runner_.running() || watch_.pending()) return;

    auto trial = [&](GlslTree tree, const std::string& stage, const Sets* sets) {
        TrialJob j = jobFor(tree, stage);
        j.overlay = tree == folders_.overlayTree ? folders_.overlay : "";
        j.width = width;
        j.height = height;
        if (sets) j.sets = *sets;
        return j;
    };
    // 1. The files of the picture on screen.
    const Record* shown = find(screen.tree, screen.stage);
    if (shown && needsFiles(*shown)) {
        TrialJob j =
            trial(screen.tree, screen.stage, screen.sets.empty() ? nullptr : &screen.sets[0]);
        startJob({false, screen.tree, screen.stage, shown->onDisk, j.sets}, j, now);
        return;
    }
    // 2. Its values (and the split view's), once its files drew.
    if (shown && shown->student && shown->adopted && !needsFiles(*shown))
        for (const Sets& sets : screen.sets)
            if (valuePending(screen.tree, screen.stage, sets)) {
                TrialJob j = trial(screen.tree, screen.stage, &sets);
                startJob({true, screen.tree, screen.stage, shown->onDisk, sets}, j, now);
                return;
            }
    // 3. The other stages of the session's tree whose files changed, in lecture order (and
    // the fixed-function stage's legacy tree in a core session).
    for (const StageInfo& s : stageRegistry()) {
        const GlslTree tree = s.legacyOnly ? GlslTree::Legacy : sessionTree;
        const Record* r = find(tree, s.id);
        if (!r || !needsFiles(*r)) continue;
        TrialJob j = trial(tree, s.id, nullptr);
        startJob({false, tree, s.id, r->onDisk, j.sets}, j, now);
        return;
    }
}

}  // namespace sl
