// Stages evaluated in bounded workers (sandbox/worker.h) under budgets calibrated on our shipped
// shaders (sandbox/budget.h), with the platform's failures told apart from the submission's:
// when our own shaders cannot finish a job, its rows are NOT GRADED (no score, exit 3, a rerun
// grades them), never the student's TIMEOUT or CRASH.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "grade/check_run.h"
#include "platform/headless.h"
#include "sandbox/budget.h"

namespace sl {

// What our shipped shaders cost for each job in this run, measured once per job (the job's cases
// without the submission): the budgets of every submission graded in this process follow from
// it. A class's job process keeps one for all its students.
class Calibration {
  public:
    Calibration(const BudgetRule& rule, Backend backend) : rule_(rule), backend_(backend) {}
    const BudgetRule& rule() const { return rule_; }
    Backend backend() const { return backend_; }
    // Our cost for `cases`, measured now or remembered; none when our shaders could not finish
    // the job here (`why` then says how).
    std::optional<JobCost> ours(const std::vector<CheckCase>& cases, std::string& why);
    std::size_t jobsMeasured() const { return cache_.size(); }

  private:
    struct Measured {
        std::optional<JobCost> cost;
        std::string why;
    };
    BudgetRule rule_;
    Backend backend_;
    std::map<std::string, Measured> cache_;
};

// The rows a worker sent back for a job (the format grade/formats.h names kWorkerRows: its
// "rows", with the worker's backend and machine), each bounded by boundResult: whatever a worker
// sends, the parent keeps rows of bounded size. Throws FormatError on another format or version,
// std::invalid_argument (or nlohmann's exception) on a malformed reply.
std::vector<CheckResult> workerResults(const WorkerOutcome& outcome);

// Every job of `plan` (one stage and tree's cases each) evaluated in bounded workers: one worker
// goes through them in order, reusing its evaluator (contexts, references) until a job fails. A
// submission's job runs under the budget's floors; one stopped there is measured against ours
// and run again under its calibrated budget when that is larger. A job that gives no results is
// one row: ERROR (a shader that does not build), TIMEOUT or CRASH (the submission's, with the
// budget it had), or NOT GRADED (our shaders fail the same way, or a GL failure).
// `each(k, results)` gets plan[k]'s results as they come.
void checkInWorkers(const std::vector<std::vector<CheckCase>>& plan,
                    const std::function<std::string(const CheckCase&)>& diffPath,
                    Calibration& calibration,
                    const std::function<void(std::size_t, std::vector<CheckResult>)>& each);

}  // namespace sl
