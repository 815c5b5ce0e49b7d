// Copy flags by pair (issue 39): which two hand-ins have the same due code, ranked by how much of
// what they wrote they share. Short natural code (one line of a shadow test) is written the same
// by honest students; a copy shares nearly everything. So a pair is measured by the share of its
// written due code in common, and only a pair at or above kCopyShareFlagged is flagged
// (docs/assignment.md "Copy flags" gives the measurement behind the threshold).
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "class/copy_flags.h"
#include "feedback/copies.h"

namespace sl {

// The tokens of `tokens` (normalizedTokens) a student wrote beyond `starter`'s: those left once
// each of the starter's tokens has been matched once (a multiset difference).
std::size_t writtenTokens(const std::vector<std::string>& tokens,
                          const std::vector<std::string>& starter);

// Every pair of `handIns` with a due file in common, the largest share first (then by names).
// `starters`: file -> what everyone was given (written tokens are counted beyond it).
std::vector<CopyPair> copyPairs(const std::vector<HandInFiles>& handIns,
                                const std::map<std::string, std::string>& starters);

}  // namespace sl
