// A measured row's judgement: a drawn row against our figures at the same values (rendered here,
// or shipped as data in a student edition) and, as a pair's second row, by how it responds to its
// parameter; a displaced row against the wider of the lesson's and the solution's bounds; any
// other row against its lesson's bounds.
#pragma once

#include <map>
#include <string>

#include "grade/check_run.h"

namespace sl {

// `shipped`: our figures for this very row, rendered beside theirs (null: none, or a student
// edition's data is looked up); `paired`: the first row of a drawn pair whose second this is.
Judgement judgeCase(const RenderRequest& request, const CheckResult& r,
                    const std::map<std::string, double>* shipped, const PairedRow* paired);

}  // namespace sl
