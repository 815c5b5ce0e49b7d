// TAs' manual adjustments (`grade --adjust adjust.csv`, docs/assignment.md "Adjustments"): points
// added or taken off one stage of one hand-in, with the reason the student reads. They are kept
// beside the records (DIR/adjustments.csv, replaced by the next --adjust) and applied when the
// outputs are drawn, so a regrade keeps them; the total stays within [0, max].
#pragma once

#include <map>
#include <string>
#include <vector>

#include "grade/record.h"

namespace sl {

// The adjustments in `text` (a CSV with the header hand-in,stage,points,reason), by hand-in
// name. `handIns`: the class's hand-in names; `stages`: the due stages ("margin" or
// "margin/core" both name one). Throws UsageError "ORIGIN: line N: what" (exit 2).
std::map<std::string, std::vector<Adjustment>> parseAdjustments(
    const std::string& text, const std::string& origin, const std::vector<std::string>& handIns,
    const std::vector<std::string>& stages);

// The class's adjustments: --adjust's file (`given`, checked, then kept as `kept`), else the
// kept ones from an earlier run, else none.
std::map<std::string, std::vector<Adjustment>> loadAdjustments(
    const std::string& given, const std::string& kept, const std::vector<std::string>& handIns,
    const std::vector<std::string>& stages);

}  // namespace sl
