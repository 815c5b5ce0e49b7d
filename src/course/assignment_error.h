// The error of a malformed assignment or of its files: exit 2, one line naming the file.
#pragma once

#include "io/usage_error.h"

namespace sl {

// A malformed assignment file: exit 2, one line "FILE: /json/path (line N): what".
class AssignmentError : public UsageError {
  public:
    using UsageError::UsageError;
};

}  // namespace sl
