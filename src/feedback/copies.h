// Possible copies as the pages show them: a flag on one file (class/copy_flags.h finds them) and a
// pair of hand-ins with due code in common (class/copy_pairs.h measures them). Found in class/,
// rendered here.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace sl {

// Two hand-ins with due files the same token for token (never the starter, never empty).
struct CopyPair {
    std::string a, b;                // a < b
    std::vector<std::string> files;  // the due files they have the same
    std::size_t commonTokens = 0;    // the written tokens of those files
    // commonTokens over the written tokens of the due files of the one who wrote more: 1 for a
    // whole copy, small for one short file in common.
    double share = 0;
};

// A pair whose share is at least this is flagged; below it, it is counted, not named.
constexpr double kCopyShareFlagged = 0.6;

// A flag on one file of hand-in `student`: the same as the published solution (`other` "") or
// as the classmates named in `other` ("bob, carol": five named, then "and N more").
struct CopyFlag {
    std::string student, file, other;
    std::string text() const;  // what the record says: "margin/lit.frag: the same as ..."
};

}  // namespace sl
