// The three JSON formats shadowlab writes and reads back, each named and versioned here and only
// here (docs/check.md, "Formats"). A reader refuses another name or version with one line naming
// what it got and what it reads. Rows in all three name their lesson by its stable id
// (expectations.json "id"), not by its label.
#pragma once

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

namespace sl {

struct Format {
    const char* name;
    int version;
};

// A worker's rows to its parent: {"format", "version", "rows": [a row as in the report],
// "backend", "machine"} (grade/stage_runs.cpp). Version 2 with the report's version 3.
inline constexpr Format kWorkerRows{"shadowlab-worker-rows", 2};
// The public report (check --report, the browser edition's report): the student's record as
// recordJson writes it, named by "report_format" and "report_version". Version 2 since rows got
// reasons (report_format and a row's expectation.id were added to it without a bump: a reader of
// version 2 reads them, or skips them); 3 since a drawn pair's reason names the figure itself
// and the row its change is from ("change_from"), where 2 ran both into its "figure".
inline constexpr Format kReport{"shadowlab-report", 3};
// The record `grade` keeps per student (OUT/students/NAME.json, with its "record_hash") and the
// solution check's parts: the report's fields plus "record_format" and "record_version". It holds
// the report: bump it whenever the report's version moves. An older one is regraded, not refused.
// Version 2 with the report's version 3.
inline constexpr Format kKeptRecord{"shadowlab-kept-record", 2};

// A JSON that is not in the format its reader reads.
class FormatError : public std::invalid_argument {
  public:
    FormatError(const std::string& what, bool older) : std::invalid_argument(what), older_(older) {}
    // Written by an older shadowlab: the same name at a lower version, or an object that names no
    // format (written before formats had names).
    bool older() const { return older_; }

  private:
    bool older_;
};

// Throws FormatError unless `j` is an object whose `nameKey` is want.name and `versionKey` is
// want.version: "a kept record: got 'shadowlab-report' version 2, reads shadowlab-kept-record
// version 1". `what` names the thing read ("a kept record", "a worker's rows").
void requireFormat(const nlohmann::json& j, const Format& want, const char* nameKey,
                   const char* versionKey, const std::string& what);

}  // namespace sl
