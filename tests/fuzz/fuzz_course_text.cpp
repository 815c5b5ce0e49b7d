// libFuzzer target: the text an instructor hands `grade` (issue 38's parsers): the CSV reader
// behind the roster, `--times` and `--adjust`, and the ISO time parser behind the deadline,
// `--times` and Gradescope's created_at. A UsageError is the expected answer to bad input; a
// crash, a sanitizer report or a broken promise of the headers is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "course/csv.h"
#include "course/iso_time.h"
#include "io/usage_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    // A time that parses is a real one: printed back in UTC, it parses to the same second.
    if (std::optional<long long> t = sl::parseIsoTime(text)) {
        if (text.size() > sl::kMaxIsoTimeBytes) __builtin_trap();
        if (sl::parseIsoTime(sl::isoUtc(*t)) != t) __builtin_trap();
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
