// What a submission's worker may use, set by what our shipped shaders cost for the same job,
// measured in the same run on the same machine (GUIDE section 7, "Load"): a grade never depends
// on how busy the machine is, and a platform that cannot run our own shaders never becomes a
// student's score. docs/check.md ("Budgets") gives the rule and the measurements behind it.
//
// A submission's job first runs under the floors (provisionalLimits): work within them is within
// any budget, so most students cost no calibration at all. A job stopped at a floor is measured
// against ours: our shaders run the same job (calibrate), and the job runs again under
// max(factor x ours, floor) when that is more.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "sandbox/worker.h"

namespace sl {

// k and the floors (measured: docs/check.md "Budgets").
constexpr double kCpuFactor = 8;           // a submission's CPU time: 8 x ours ...
constexpr double kCpuFloorSeconds = 30;    // ... and at least 30 s
constexpr double kMemoryFactor = 2;        // resident memory: 2 x our peak ...
constexpr long kMemoryFloorMb = 512;       // ... and at least 512 MB, within the box
constexpr double kWallFactor = 10;         // the wall-clock backstop: 10 x the CPU budget ...
constexpr double kWallFloorSeconds = 300;  // ... and at least 300 s
constexpr double kOursWallSeconds = 900;   // our own shaders: the backstop alone

// How the limits are chosen: each one fixed by the user, or calibrated (auto).
struct BudgetRule {
    std::optional<double> cpuSeconds;  // --time-limit S (0: none); unset: auto
    std::optional<long> memoryMb;      // --memory-limit MB (0: none); unset: auto
    long memoryCeilingMb = 2048;       // what the box lets one worker hold (io/box.h)
    bool calibrated() const { return !cpuSeconds || !memoryMb; }
};

// The rule the options give: "auto" or a number ("0": no limit). Throws UsageError naming the
// option on anything else.
BudgetRule budgetRuleFrom(const std::string& timeLimit, const std::string& memoryLimit);

// What one job cost our shipped shaders.
struct JobCost {
    double cpuSeconds = 0, wallSeconds = 0;
    long peakMb = 0;
};

// A submission's job before calibration: the floors (or the fixed limits).
Limits provisionalLimits(const BudgetRule& rule);
// A submission's job once ours were measured: max(factor x ours, floor), within the ceiling.
Limits submissionLimits(const BudgetRule& rule, const JobCost& ours);
// Our own shaders' jobs: no CPU budget (they are the measure), the backstop, the box's memory.
Limits oursLimits(const BudgetRule& rule);

// Whether a job that ended so under `provisional` may yet finish under a calibrated budget:
// it was stopped at a floor the rule may raise.
bool stoppedAtFloor(const BudgetRule& rule, const WorkerOutcome& outcome);

// How a budget came about, for the message of a job that ran out of it: its CPU time
// (`cpu`) or its memory ("the larger of 8 x our shaders' 2.1 s and 30 s").
std::string budgetExplained(const BudgetRule& rule, const JobCost& ours, bool cpu);

}  // namespace sl
