#include "course/gradebook_exports.h"

#include <cstdio>
#include <sstream>

#include "course/feedback_html.h"

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
        out << csvCell(who.name.empty() ? r.student : who.name) << ",," << csvCell(who.id) << ",,,"
            << totalCell(r) << "\r\n";
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

}  // namespace sl
