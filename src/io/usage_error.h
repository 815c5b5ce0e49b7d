// The command line's contract at the bottom of every floor: a user's (or a student's) mistake is
// a UsageError (exit 2, one line), and the exit codes every command returns.
#pragma once

#include <stdexcept>

namespace sl {

// Exit codes of the command-line contract.
enum ExitCode { kOk = 0, kCheckFailed = 1, kBadInput = 2, kGlFailure = 3 };

// A bad value given by the user: the command says it in one line and exits kBadInput.
class UsageError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

}  // namespace sl
