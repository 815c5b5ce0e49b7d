#include "feedback/copies.h"

namespace sl {

std::string CopyFlag::text() const {
    return file + ": the same as " +
           (other.empty() ? "the published solution" : "the hand-in of " + other) +
           " once whitespace, comments and names are set aside (a flag to look at, not a score)";
}

}  // namespace sl
