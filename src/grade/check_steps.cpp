#include "grade/check_steps.h"

#include <stdexcept>

#include "gl/loop_guard.h"

namespace sl {

CheckSteps::CheckSteps(GradingPlan plan, StudentWork work, std::optional<std::uint64_t> seed,
                       std::function<std::string(const CheckCase&)> diffPath)
    : plan_(std::move(plan)),
      work_(std::move(work)),
      seed_(seed),
      diffPath_(std::move(diffPath)),
      rig_(std::make_unique<Evaluator>(Backend::Auto)) {
    for (const StagePlan& st : plan_.stages) rowCount_ += st.rows.size();
}

CheckSteps::~CheckSteps() = default;

std::size_t CheckSteps::rowsDone() const {
    return rowsBefore_ + (series_ ? series_->results().size() : 0);
}

void CheckSteps::finishStage(std::vector<StageRecord>& made) {
    const StagePlan& p = plan_.stages[stage_];
    const std::vector<CheckResult>* got = nullptr;
    if (!failed_.empty())
        got = &failed_;
    else if (series_)
        got = &series_->results();
    stages_.push_back(stageRecord(p, got, work_.overlay));
    made.push_back(stages_.back());
    rowsBefore_ += p.rows.size();
    series_.reset();
    failed_.clear();
    rig_->dropGiven();
    offered_.clear();  // a later stage may need a view again once the Evaluator let it go
    ++stage_;
}

std::vector<TraceView> CheckSteps::viewsToTrace() {
    std::vector<TraceView> views;
    if (series_) return views;
    std::size_t next = stage_;
    while (next < plan_.stages.size() && !plan_.stages[next].rendered()) ++next;
    if (next == plan_.stages.size()) return views;
    std::vector<const RenderRequest*> requests;
    for (const RowPlan& row : plan_.stages[next].rows) requests.push_back(&row.check.request);
    for (std::optional<TraceView>& view : traceViewsOf(requests)) {
        if (!view) continue;  // a scene that does not load fails in its row
        const std::string key = traceKey(*view);
        if (rig_->keepReference(key) || !offered_.insert(key).second) continue;
        views.push_back(std::move(*view));
    }
    return views;
}

void CheckSteps::giveReference(const std::string& key, ReferenceImage reference) {
    rig_->giveReference(key, std::move(reference));
}

std::vector<StageRecord> CheckSteps::step() {
    std::vector<StageRecord> made;
    lastRow_.reset();
    while (!done() && !plan_.stages[stage_].rendered()) finishStage(made);
    if (done()) return made;
    const StagePlan& p = plan_.stages[stage_];
    if (!series_) {
        std::vector<CheckCase> cases;
        for (const RowPlan& row : p.rows) cases.push_back(row.check);
        series_ = std::make_unique<CaseSeries>(*rig_, std::move(cases), diffPath_);
    }
    try {
        lastRow_ = series_->next();
    } catch (const LoopBudgetSpent& e) {
        // The browser's loop budget stopped the student's loop: theirs, as native check's
        // CPU-time budget makes it (TIMEOUT for every row of the stage; docs/web.md).
        CheckResult r = unrenderedResult(p.rows[series_->results().size()].check.request);
        r.status = Status::Timeout;
        r.message = "stage " + p.stage + " (" + p.tree + "): " + e.what();
        failed_ = {r};
        lastRow_ = r;
        rig_->reset();
    } catch (const std::exception& e) {
        // The browser's GL failed (a lost context, an out-of-memory): never the student's.
        CheckResult r = unrenderedResult(p.rows[series_->results().size()].check.request);
        r.status = Status::NotGraded;
        r.message = std::string("the browser could not finish this row: ") +
                    (rig_->contextLost() ? contextLostMessage(p.stage) : e.what());
        failed_ = {r};
        lastRow_ = r;
        rig_->reset();
    }
    if (!failed_.empty() || series_->done()) finishStage(made);
    return made;
}

StudentRecord CheckSteps::record() const {
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    GradingPlan made = plan_;
    made.stages.resize(stages_.size());
    StudentRecord r = buildRecord(made, work_, stages_, seconds);
    r.seed = seed_;
    return r;
}

}  // namespace sl
