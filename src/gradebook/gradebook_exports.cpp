#include "gradebook/gradebook_exports.h"

#include <cstdio>
#include <sstream>

#include "feedback/html_text.h"
#include "io/files.h"

namespace sl {

namespace {

std::string totalCell(const StudentRecord& r) {
    if (!r.graded()) return "";
    char t[32];
    std::snprintf(t, sizeof t, "%.2f", r.total());
    return t;
}

}  // namespace

std::string canvasCsv(const std::string& assignment, const std::vector<StudentRecord>& records) {
    // Canvas matches a row by ID, SIS User ID or SIS Login ID (any one), then by Student; the
    // roster's id is the institution's (SIS) id. A column named without "(id)" creates the
    // assignment on import; rename it "NAME (id)" as Canvas's export shows to update one.
    std::ostringstream out;
    out << "Student,ID,SIS User ID,SIS Login ID,Section," << csvCell(assignment) << "\r\n";
    for (const StudentRecord& r : records) {
        const RosterInfo who = r.roster.value_or(RosterInfo{});
        out << csvCell(who.name.empty() ? escapedName(r.student) : who.name) << ",,"
            << csvCell(who.id) << ",,," << totalCell(r) << "\r\n";
    }
    return out.str();
}

std::string moodleCsv(const std::string& assignment, const std::vector<StudentRecord>& records) {
    // Moodle's import maps one column to a user field ("Identify user by": ID number or email
    // address) and a column to a grade item; both identifiers are given, the instructor picks.
    std::ostringstream out;
    out << "ID number,Email address," << csvCell(assignment) << "\r\n";
    for (const StudentRecord& r : records) {
        const RosterInfo who = r.roster.value_or(RosterInfo{});
        out << csvCell(who.id) << "," << csvCell(who.email) << "," << totalCell(r) << "\r\n";
    }
    return out.str();
}

std::string csvCell(const std::string& s) {
    std::string v = validUtf8(s);
    // A spreadsheet evaluates a cell that starts with = + - @, a TAB or a CR, or their
    // full-width forms (U+FF1D = , U+FF0B + , U+FF0D - , U+FF20 @): prefixed, never a formula
    // (OWASP's CSV injection rule).
    static const char* const kFormulaStarts[] = {
        "=",           "+", "-", "@", "\t", "\r", "\xEF\xBC\x9D", "\xEF\xBC\x8B", "\xEF\xBC\x8D",
        "\xEF\xBC\xA0"};
    for (const char* start : kFormulaStarts)
        if (v.rfind(start, 0) == 0) {
            v = "'" + v;
            break;
        }
    // RFC 4180: a field holding a comma, a quote or a line break is quoted, quotes doubled.
    if (v.find_first_of(",\"\n\r") == std::string::npos) return v;
    std::string out = "\"";
    for (char c : v) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string gradesCsv(const std::vector<StudentRecord>& records) {
    std::ostringstream out;
    out << "student,id,name,email,status";
    if (!records.empty())
        for (const StageRecord& st : records.front().stages)
            out << "," << csvCell(st.stage + "/" + st.tree);
    out << ",adjustments,late_penalty,total,max,not_graded\r\n";
    for (const StudentRecord& r : records) {
        const RosterInfo who = r.roster.value_or(RosterInfo{});
        out << csvCell(escapedName(r.student)) << "," << csvCell(who.id) << "," << csvCell(who.name)
            << "," << csvCell(who.email) << "," << csvCell(statusName(r.status()));
        std::string reasons;
        for (const StageRecord& st : r.stages) {
            // A stage that is not graded has no points, not 0: an empty cell, the reason last.
            if (st.status == Status::NotGraded) {
                out << ",";
                reasons +=
                    (reasons.empty() ? "" : "; ") + st.stage + "/" + st.tree + ": " + st.message;
            } else {
                out << "," << numText(st.points, 3);
            }
        }
        double adjusted = 0;
        for (const Adjustment& a : r.adjustments) adjusted += a.points;
        out << "," << (r.adjustments.empty() ? "" : numText(adjusted, 3)) << ","
            << (r.late ? numText(r.late->penalty, 3) : "");
        if (r.graded())
            out << "," << numText(r.total(), 3) << "," << numText(r.maxScore, 3) << ",";
        else
            out << ",,," << csvCell(reasons);
        out << "\r\n";
    }
    return out.str();
}

}  // namespace sl
