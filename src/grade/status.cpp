#include "grade/status.h"

namespace sl {

namespace {

constexpr const char* kNames[] = {"PASS",  "SKIP",    "FAIL",  "MISSING",
                                  "ERROR", "TIMEOUT", "CRASH", "NOT GRADED"};

}  // namespace

const char* statusName(Status s) {
    return kNames[static_cast<int>(s)];
}

std::optional<Status> statusFromName(const std::string& name) {
    for (int k = 0; k <= static_cast<int>(Status::NotGraded); ++k)
        if (name == kNames[k]) return static_cast<Status>(k);
    return std::nullopt;
}

int exitCodeOf(Status s) {
    switch (s) {
        case Status::Pass:
        case Status::Skip:
            return 0;
        case Status::Fail:
            return 1;
        case Status::NotGraded:
            return 3;
        default:
            return 2;
    }
}

bool earnsPoints(Status s) {
    return s == Status::Pass || s == Status::Skip;
}

}  // namespace sl
