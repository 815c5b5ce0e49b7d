#include "gradebook/adjustments.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "gradebook/csv.h"
#include "io/files.h"
#include "io/usage_error.h"

namespace sl {

std::map<std::string, std::vector<Adjustment>> parseAdjustments(
    const std::string& text, const std::string& origin, const std::vector<std::string>& handIns,
    const std::vector<std::string>& stages) {
    std::vector<CsvRecord> rows = parseCsv(text, origin, 100001);
    if (rows.empty()) csvFail(origin, 1, "empty: give a header row hand-in,stage,points,reason");
    const std::vector<std::string> header = {"hand-in", "stage", "points", "reason"};
    if (rows.front().fields != header)
        csvFail(origin, rows.front().line, "the header must be hand-in,stage,points,reason");
    std::map<std::string, std::vector<Adjustment>> out;
    for (std::size_t k = 1; k < rows.size(); ++k) {
        const CsvRecord& r = rows[k];
        if (r.fields.size() != 4)
            csvFail(origin, r.line,
                    std::to_string(r.fields.size()) +
                        " fields, expected 4 (hand-in,stage,points,reason; quote a reason "
                        "holding a comma)");
        const std::string* name = handInNamed(handIns, r.fields[0]);
        if (!name)
            csvFail(origin, r.line,
                    "no hand-in named '" + printableName(r.fields[0]) + "' in the class");
        if (std::find(stages.begin(), stages.end(), r.fields[1]) == stages.end())
            csvFail(origin, r.line,
                    "'" + printableName(r.fields[1]) + "' is not a due stage of the assignment");
        char* end = nullptr;
        const double points = std::strtod(r.fields[2].c_str(), &end);
        if (r.fields[2].empty() || *end != '\0' || !std::isfinite(points) || std::abs(points) > 1e6)
            csvFail(origin, r.line,
                    "points '" + printableName(r.fields[2]) + "' is not a number like 2 or -1.5");
        if (r.fields[3].empty())
            csvFail(origin, r.line, "no reason (the student reads it on their page)");
        out[*name].push_back({r.fields[1], points, r.fields[3]});
    }
    return out;
}

std::map<std::string, std::vector<Adjustment>> loadAdjustments(
    const std::string& given, const std::string& kept, const std::vector<std::string>& handIns,
    const std::vector<std::string>& stages) {
    const std::string& path = given.empty() ? kept : given;
    std::string text;
    std::string err = readRegularFile(path, kCsvMaxBytes, text);
    if (!err.empty()) {
        if (given.empty()) return {};  // none kept
        throw UsageError("--adjust: " + printableName(given) + ": " + err);
    }
    auto adjustments = parseAdjustments(text, path, handIns, stages);
    if (!given.empty()) {
        err = writeFileAtomically(kept, text.data(), text.size());
        if (!err.empty()) throw UsageError("grade: " + err);
    }
    return adjustments;
}

}  // namespace sl
