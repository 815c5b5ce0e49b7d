#include "course/solution_markers.h"

#include <cstring>
#include <functional>
#include <sstream>

#include "io/files.h"

namespace sl {

namespace {

std::string trimmed(const std::string& s) {
    std::size_t a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
    return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

// The exact marker lines (trimmed) and the STUB prefix.
const char* const kBegin = "// BEGIN SOLUTION";
const char* const kEnd = "// END SOLUTION";
const char* const kStub = "// STUB:";

enum class Marker { None, Begin, End, Stub };

// A line's words as markers are matched: runs of ASCII letters and digits, lower-cased. Every
// other character separates words, in any number: spaces, tabs, punctuation, and any non-ASCII
// character (U+00A0, U+2000-U+200A, U+3000, dashes U+2010-U+2015 and U+2212...), except the
// invisible ones, which join (U+200B-U+200D, U+2060, U+FEFF, U+00AD: "SOLU\u200BTION" is one
// word). `lead` is what comes before the first word. One pass, no backtracking: a line of a
// million spaces costs a million steps, never the stack.
struct LineWords {
    std::vector<std::string> words;
    std::string lead;
};

LineWords wordsOf(const std::string& line) {
    LineWords out;
    std::string word;
    auto endWord = [&]() {
        if (!word.empty()) out.words.push_back(word);
        word.clear();
    };
    for (std::size_t i = 0; i < line.size();) {
        unsigned char c = static_cast<unsigned char>(line[i]);
        if (c < 0x80) {
            if (std::isalnum(c)) {
                word += char(std::tolower(c));
            } else {
                endWord();
                if (out.words.empty()) out.lead += char(c);
            }
            ++i;
            continue;
        }
        std::size_t length = (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 1;
        unsigned code = length == 1 ? c : c & (0xff >> (length + 1));
        for (std::size_t k = 1; k < length && i + k < line.size(); ++k)
            code = code << 6 | (static_cast<unsigned char>(line[i + k]) & 0x3f);
        const bool invisible = (code >= 0x200B && code <= 0x200D) || code == 0x2060 ||
                               code == 0xFEFF || code == 0x00AD;
        if (!invisible) endWord();
        if (out.words.empty() && word.empty()) out.lead += line.substr(i, length);
        i += length;
    }
    endWord();
    return out;
}

bool endsWith(const std::string& s, const char* tail) {
    std::size_t n = std::strlen(tail);
    return s.size() >= n && s.compare(s.size() - n, n, tail) == 0;
}

// Whether the words read like a marker: BEGIN or END next to SOLUTION (either order, joined or
// apart), or a comment whose first word is STUB.
bool looksLikeMarker(const LineWords& w) {
    for (std::size_t k = 0; k < w.words.size(); ++k) {
        const std::string& a = w.words[k];
        if (a.find("beginsolution") != std::string::npos ||
            a.find("endsolution") != std::string::npos || endsWith(a, "solutionbegin") ||
            endsWith(a, "solutionend"))
            return true;
        if (k + 1 == w.words.size()) break;
        const std::string& b = w.words[k + 1];
        if ((endsWith(a, "begin") || endsWith(a, "end")) && b.rfind("solution", 0) == 0)
            return true;
        if (endsWith(a, "solution") && (b == "begin" || b == "end")) return true;
    }
    return !w.words.empty() && w.words.front() == "stub" &&
           w.lead.find_first_of("/*") != std::string::npos;
}

// What a line is, tolerantly: anything that looks like a marker (any case, any spacing,
// Unicode spaces, invisible characters or punctuation between the words, inside a block
// comment, after code, the words swapped) but is not the exact form refuses, so a misspelled
// marker never ships its region's solution.
Marker markerOf(const std::string& line, const std::function<AssignmentError(std::string)>& at) {
    std::string t = trimmed(line);
    if (t == kBegin) return Marker::Begin;
    if (t == kEnd) return Marker::End;
    if (t.rfind(kStub, 0) == 0) return Marker::Stub;
    if (looksLikeMarker(wordsOf(line))) {
        std::string shown = t.size() > 60 ? t.substr(0, 57) + "..." : t;
        throw at("'" + printableName(shown) +
                 "' looks like a solution marker but is not one; write exactly '" + kBegin +
                 "', '" + kEnd + "' or '" + kStub + " code' on a line of its own");
    }
    return Marker::None;
}

}  // namespace

std::string stripSolutions(const std::string& text, const std::string& origin,
                           std::vector<std::string>* solution) {
    std::istringstream in(text);
    std::ostringstream out;
    std::string line;
    int number = 0, begin = 0;
    bool inRegion = false, afterRegion = false, sawStub = false;
    std::string indent;
    auto closeRegion = [&]() {
        if (afterRegion && !sawStub) out << indent << "// TODO: write this part\n";
        afterRegion = false;
    };
    auto at = [&](const std::string& what) {
        return AssignmentError(origin + ": line " + std::to_string(number) + ": " + what);
    };
    while (std::getline(in, line)) {
        ++number;
        Marker m = markerOf(line, at);
        if (m == Marker::Begin) {
            if (inRegion)
                throw at("BEGIN SOLUTION inside the region opened on line " +
                         std::to_string(begin));
            closeRegion();
            inRegion = true;
            begin = number;
            indent = line.substr(0, line.find('/'));
            continue;
        }
        if (m == Marker::End) {
            if (!inRegion) throw at("END SOLUTION without a BEGIN SOLUTION");
            inRegion = false;
            afterRegion = true;
            sawStub = false;
            continue;
        }
        if (inRegion) {
            if (m == Marker::Stub)
                throw at("a STUB line inside the region opened on line " + std::to_string(begin));
            if (solution) solution->push_back(line);
            continue;
        }
        if (m == Marker::Stub) {
            if (!afterRegion) throw at("a STUB line not right after an END SOLUTION");
            std::string code = trimmed(line).substr(std::strlen(kStub));
            if (!code.empty() && code[0] == ' ') code.erase(0, 1);
            // The code a STUB hands out is never a marker (or a look-alike, which markerOf
            // refuses): the release would carry a line a later release reads as one (the fuzzer's
            // find: "// STUB: // BEGIN SOLUTION").
            if (markerOf(code, at) != Marker::None) throw at("a STUB line whose code is a marker");
            out << line.substr(0, line.find('/')) << code << "\n";
            sawStub = true;
            continue;
        }
        closeRegion();
        out << line << "\n";
    }
    if (inRegion)
        throw AssignmentError(origin + ": line " + std::to_string(begin) +
                              ": BEGIN SOLUTION is never closed");
    closeRegion();
    std::string result = out.str();
    if (!text.empty() && text.back() != '\n' && !result.empty()) result.pop_back();
    return result;
}

}  // namespace sl
