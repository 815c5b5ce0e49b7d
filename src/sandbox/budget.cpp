#include "sandbox/budget.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "io/usage_error.h"

namespace sl {

namespace {

// "auto" -> unset; a number within [0, most] -> it; else UsageError.
template <typename T>
std::optional<T> limitValue(const std::string& option, const std::string& text, double most) {
    if (text == "auto") return std::nullopt;
    char* end = nullptr;
    double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != 0 || !std::isfinite(v) || v < 0 || v > most)
        throw UsageError(option + ": '" + text + "' is not auto or a number from 0 to " +
                         std::to_string(long(most)) + " (0 = no limit)");
    return static_cast<T>(v);
}

std::string seconds(double s) {
    char t[32];
    std::snprintf(t, sizeof t, "%.3g s", s);
    return t;
}

}  // namespace

BudgetRule budgetRuleFrom(const std::string& timeLimit, const std::string& memoryLimit) {
    BudgetRule rule;
    rule.cpuSeconds = limitValue<double>("--time-limit", timeLimit, 86400);
    rule.memoryMb = limitValue<long>("--memory-limit", memoryLimit, double(1L << 24));
    return rule;
}

Limits provisionalLimits(const BudgetRule& rule) {
    Limits l;
    l.cpuSeconds = rule.cpuSeconds ? *rule.cpuSeconds : kCpuFloorSeconds;
    l.wallSeconds = l.cpuSeconds > 0 ? std::max(kWallFloorSeconds, kWallFactor * l.cpuSeconds) : 0;
    l.memoryMb = rule.memoryMb ? *rule.memoryMb : std::min(rule.memoryCeilingMb, kMemoryFloorMb);
    return l;
}

Limits submissionLimits(const BudgetRule& rule, const JobCost& ours) {
    Limits l = provisionalLimits(rule);
    if (!rule.cpuSeconds) {
        l.cpuSeconds = std::max(kCpuFloorSeconds, kCpuFactor * ours.cpuSeconds);
        l.wallSeconds = std::max(kWallFloorSeconds, kWallFactor * l.cpuSeconds);
    }
    if (!rule.memoryMb)
        l.memoryMb = std::min(rule.memoryCeilingMb,
                              std::max(kMemoryFloorMb, long(kMemoryFactor * double(ours.peakMb))));
    return l;
}

Limits oursLimits(const BudgetRule& rule) {
    Limits l;
    const bool unlimited = rule.cpuSeconds && *rule.cpuSeconds == 0;  // --time-limit 0
    l.wallSeconds = unlimited ? 0 : kOursWallSeconds;
    l.memoryMb = rule.memoryMb ? *rule.memoryMb : rule.memoryCeilingMb;
    return l;
}

bool stoppedAtFloor(const BudgetRule& rule, const WorkerOutcome& o) {
    if (o.kind == WorkerOutcome::Kind::Timeout) return !rule.cpuSeconds;
    if (o.kind == WorkerOutcome::Kind::Crash && o.outOfMemory) return !rule.memoryMb;
    return false;
}

std::string budgetExplained(const BudgetRule& rule, const JobCost& ours, bool cpu) {
    std::string cpuText = rule.cpuSeconds ? "fixed by --time-limit"
                                          : "the larger of " + std::to_string(int(kCpuFactor)) +
                                                " x our shaders' " + seconds(ours.cpuSeconds) +
                                                " and " + seconds(kCpuFloorSeconds);
    std::string mem = rule.memoryMb
                          ? "fixed by --memory-limit"
                          : "the larger of " + std::to_string(int(kMemoryFactor)) + " x our " +
                                std::to_string(ours.peakMb) + " MB and " +
                                std::to_string(kMemoryFloorMb) + " MB, within the " +
                                std::to_string(rule.memoryCeilingMb) + " MB the box gives";
    return cpu ? "CPU time " + cpuText : "memory " + mem;
}

}  // namespace sl
