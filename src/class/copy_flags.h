// Copy flags (docs/assignment.md "Copy flags"): a hand-in's due file that is, token for token,
// the published solution or a classmate's, once whitespace, comments and the names the author
// chose are set aside. A flag is for the instructor to look at, never a score: it is shown on
// the class page and kept in the record (`flags`), and changes no point.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "feedback/copies.h"

namespace sl {

// GLSL source as tokens: comments and whitespace dropped; every identifier that is not a GLSL
// keyword, type, built-in function or variable (gl_*) or a preprocessor word replaced by a
// placeholder ("$0", "$1", ...) in order of first use. Two shaders that differ only in layout,
// comments and their own names give the same tokens.
std::vector<std::string> normalizedTokens(const std::string& source);

// One student's due files: file (relative to the tree, "margin/lit.frag") -> its text.
struct HandInFiles {
    std::string name;
    std::map<std::string, std::string> files;
};

// The flags of a class: for each due file, every hand-in equal to its published solution
// (`solutions`: file -> the solution's whole text), and the files of every pair of hand-ins
// that shares at least kCopyShareFlagged of its written due code (class/copy_pairs.h). A file
// equal to its starter (`starters`: what everyone was given) is never flagged.
std::vector<CopyFlag> findCopies(const std::vector<HandInFiles>& handIns,
                                 const std::map<std::string, std::string>& solutions,
                                 const std::map<std::string, std::string>& starters);

}  // namespace sl
