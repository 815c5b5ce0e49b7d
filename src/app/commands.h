// Each subcommand adds itself to the CLI and returns the exit code when it runs.
#pragma once

#include <functional>

#include "app/options.h"

namespace sl {

// A subcommand and what to run when the user chose it.
struct Command {
    CLI::App* sub;
    std::function<int()> run;
};

// Each returns the function to call when its subcommand was chosen.
Command addStagesCommand(CLI::App& app);
Command addRenderCommand(CLI::App& app);
Command addWindowCommand(CLI::App& app);
Command addBenchCommand(CLI::App& app);
Command addSweepCommand(CLI::App& app);
Command addCheckCommand(CLI::App& app);
Command addExampleCommand(CLI::App& app);
Command addReleaseCommand(CLI::App& app);
Command addGradeCommand(CLI::App& app);

// Runs `body`, turning the project's exceptions into the contract's exit codes and one-line
// messages on stderr.
int guarded(const std::function<int()>& body);

}  // namespace sl
