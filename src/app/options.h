// The command line's common options (GUIDE section 3), parsed from text with one-line errors.
#pragma once

#include <CLI/CLI.hpp>

#include "platform/headless.h"
#include "sandbox/budget.h"
#include "stages/registry.h"
#include "stages/request.h"

namespace sl {

struct CommonOptions {
    // scene "" = not given: slides, or the stage's own default scene (StageInfo::defaultScene)
    std::string stage = lightingStage().id, glsl = "core", scene, shaders, size = "640x480";
    std::string eye, at, fovy, light, view = "final", backend = "auto";
    std::optional<std::uint64_t> displace;  // --displace SEED: check's displaced view
    std::vector<std::string> sets;
};

// Adds the common options to a subcommand; `withStage` = false for commands that pick stages
// themselves (check --all, bench).
void addCommonOptions(CLI::App* app, CommonOptions& o, bool withStage = true);

// Turns the text into a request; throws UsageError naming the option and what is allowed.
RenderRequest toRequest(const CommonOptions& o);

// --time-limit auto|SECONDS (CPU time) and --memory-limit auto|MB (resident) of the workers,
// as text until the command runs: rule() turns them into the budget rule (sandbox/budget.h).
struct LimitOptions {
    std::string time = "auto", memory = "auto";
    BudgetRule rule() const;
};
void addLimitOptions(CLI::App* app, LimitOptions& limits);
Backend toBackend(const std::string& text);

}  // namespace sl
