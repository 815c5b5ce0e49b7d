// CSV files an instructor gives `grade` (the roster, the hand-in times): RFC 4180 records, UTF-8
// with or without a byte order mark; every error is exit 2 with the file and the line.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace sl {

constexpr std::size_t kCsvMaxBytes = 16u << 20;

struct CsvRecord {
    std::vector<std::string> fields;
    int line = 0;  // the line it starts on
};

// The records of `text` (CRLF or LF line ends; a quoted field may hold commas, doubled quotes
// and line breaks; blank lines skipped; at most `maxRecords`). Throws UsageError
// "ORIGIN: line N: what" on a stray or unterminated quote or bytes that are not UTF-8.
// A field holds at most kCsvMaxFieldBytes; past `maxRecords` (the header included) the error
// names the limit of rows after the header, as `rowsAre` ("students") counts them.
constexpr std::size_t kCsvMaxFieldBytes = 4096;
std::vector<CsvRecord> parseCsv(const std::string& text, const std::string& origin,
                                std::size_t maxRecords,
                                const std::string& rowsAre = "rows after the header");

// The file at `path` (at most 16 MiB) as parseCsv reads it; `option` names it in errors.
std::vector<CsvRecord> loadCsv(const std::string& path, const std::string& option,
                               std::size_t maxRecords);

// Throws UsageError "ORIGIN: line N: what".
[[noreturn]] void csvFail(const std::string& origin, int line, const std::string& what);

}  // namespace sl
