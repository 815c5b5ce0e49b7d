#include "gradebook/csv.h"

#include <algorithm>

#include "io/files.h"
#include "io/usage_error.h"

namespace sl {

void csvFail(const std::string& origin, int line, const std::string& what) {
    throw UsageError(printableName(origin) + ": line " + std::to_string(line) + ": " + what);
}

namespace {

std::vector<CsvRecord> records(const std::string& text, const std::string& origin,
                               std::size_t maxRecords, const std::string& rowsAre) {
    auto fail = [&](int line, const std::string& what) { csvFail(origin, line, what); };
    std::vector<CsvRecord> out;
    int line = 1;
    std::size_t i = 0;
    while (i < text.size()) {
        if (text[i] == '\n' || (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n')) {
            i += text[i] == '\r' ? 2 : 1;  // a blank line
            ++line;
            continue;
        }
        CsvRecord rec;
        rec.line = line;
        for (;;) {  // one field per round
            std::string field;
            if (i < text.size() && text[i] == '"') {
                const int opened = line;
                for (++i;; ++i) {
                    if (i >= text.size()) fail(opened, "a quoted field is never closed");
                    if (text[i] == '"') {
                        if (i + 1 < text.size() && text[i + 1] == '"') {
                            field += '"';
                            ++i;
                            continue;
                        }
                        ++i;
                        break;
                    }
                    if (text[i] == '\n') ++line;
                    field += text[i];
                }
                if (i < text.size() && text[i] != ',' && text[i] != '\n' && text[i] != '\r')
                    fail(line, "text after a closing quote (a quote inside a field is doubled)");
            } else {
                while (i < text.size() && text[i] != ',' && text[i] != '\n' && text[i] != '\r') {
                    if (text[i] == '"')
                        fail(line,
                             "a quote inside an unquoted field (quote the field, double "
                             "the quote)");
                    field += text[i++];
                }
            }
            if (field.size() > kCsvMaxFieldBytes)  // no name, time or reason is that long
                fail(rec.line, "a field of " + std::to_string(field.size()) + " bytes; at most " +
                                   std::to_string(kCsvMaxFieldBytes) + " are allowed");
            rec.fields.push_back(field);
            if (i < text.size() && text[i] == ',') {
                ++i;
                continue;
            }
            if (i < text.size() && text[i] == '\r') {
                if (i + 1 >= text.size() || text[i + 1] != '\n')
                    fail(line, "a carriage return that does not end a line");
                ++i;
            }
            if (i < text.size() && text[i] == '\n') {
                ++i;
                ++line;
            }
            break;
        }
        out.push_back(std::move(rec));
        if (out.size() > maxRecords)  // the header and maxRecords - 1 rows
            fail(out.back().line,
                 "more than " + std::to_string(maxRecords - 1) + " " + rowsAre + " (the limit)");
    }
    return out;
}

}  // namespace

std::vector<CsvRecord> parseCsv(const std::string& input, const std::string& origin,
                                std::size_t maxRecords, const std::string& rowsAre) {
    std::string text = input;
    if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);  // a byte order mark
    const std::string good = validUtf8(text);
    if (good != text) {
        std::size_t at = 0;
        while (at < text.size() && at < good.size() && text[at] == good[at]) ++at;
        csvFail(origin, int(std::count(text.begin(), text.begin() + long(at), '\n')) + 1,
                "not UTF-8 (save the file as UTF-8)");
    }
    return records(text, origin, maxRecords, rowsAre);
}

std::vector<CsvRecord> loadCsv(const std::string& path, const std::string& option,
                               std::size_t maxRecords) {
    std::string text;
    std::string err = readRegularFile(path, kCsvMaxBytes, text);
    if (!err.empty()) throw UsageError(option + ": " + printableName(path) + ": " + err);
    return parseCsv(text, path, maxRecords);
}

}  // namespace sl
