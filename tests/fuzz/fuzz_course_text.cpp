// libFuzzer target: the text an instructor hands `grade` and `release` (issue 38's parsers): the
// CSV reader behind the roster, `--times` and `--adjust`, the ISO time parser behind the
// deadline, `--times` and Gradescope's created_at, and the solution markers `release` strips. A
// UsageError is the expected answer to bad input; a crash, a sanitizer report or a broken promise
// of the headers is a bug.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "course/solution_markers.h"
#include "gradebook/csv.h"
#include "gradebook/iso_time.h"
#include "io/usage_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    // A time that parses is a real one: printed back in UTC, it parses to the same second.
    if (std::optional<long long> t = sl::parseIsoTime(text)) {
        if (text.size() > sl::kMaxIsoTimeBytes) __builtin_trap();
        if (sl::parseIsoTime(sl::isoUtc(*t)) != t) __builtin_trap();
    }
    // What release hands out holds no marker line: every region it saw is gone.
    try {
        std::vector<std::string> removed;
        const std::string stripped = sl::stripSolutions(text, "fuzz.frag", &removed);
        if (stripped.size() > text.size() + 64 * (removed.size() + 1) + 32) __builtin_trap();
        // No marker line survives (a STUB's code may mention one: that is not a region).
        std::istringstream lines(stripped);
        for (std::string line; std::getline(lines, line);) {
            const std::size_t a = line.find_first_not_of(" \t\r");
            const std::string t = a == std::string::npos ? "" : line.substr(a);
            if (t.rfind("// BEGIN SOLUTION", 0) == 0 || t.rfind("// END SOLUTION", 0) == 0)
                __builtin_trap();
        }
    } catch (const sl::UsageError&) {
        // a marker out of place or a look-alike, refused with its line
    }
    try {
        const std::size_t maxRecords = 64;
        for (const sl::CsvRecord& r : sl::parseCsv(text, "fuzz.csv", maxRecords)) {
            if (r.line < 1) __builtin_trap();
            for (const std::string& f : r.fields)
                if (f.size() > sl::kCsvMaxFieldBytes) __builtin_trap();
            sl::parseIsoTime(r.fields.empty() ? std::string() : r.fields.back());
        }
    } catch (const sl::UsageError&) {
        // bad input, reported cleanly
    }
    return 0;
}
