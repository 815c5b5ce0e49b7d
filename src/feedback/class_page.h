// The class page `grade` writes (docs/assignment.md, "A class"): students by stages, linked to
// their pages, each stage's commonest failure, and for the instructor only the source rules'
// notes, the possible copies and what the class folder held that was not a hand-in.
#pragma once

#include <string>
#include <vector>

#include "feedback/copies.h"
#include "grade/record.h"

namespace sl {

// The class's possible copies (class/copy_pairs.h), for the instructor: the pairs ranked by
// the share of their written due code in common, and the files equal to the published solution.
struct ClassCopies {
    std::vector<CopyPair> pairs;
    std::vector<CopyFlag> solution;
};

// Students by stages, coloured by points, each linked to `pages[k]`; per stage its most common
// failure and how many students had it; `skipped`: the class folder's entries left out
// ("NAME (why)"), listed so none is silently dropped; `copies`: one row per pair at or above
// kCopyShareFlagged, the largest share first, the pairs below it counted.
std::string classPage(const std::string& assignment, const std::vector<StudentRecord>& records,
                      const std::vector<std::string>& pages,
                      const std::vector<std::string>& skipped = {}, const ClassCopies& copies = {});

}  // namespace sl
