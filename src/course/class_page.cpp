#include "course/class_page.h"

#include <map>
#include <set>
#include <sstream>

#include "course/html_text.h"
#include "io/files.h"

namespace sl {

namespace {

// What a student's stage shows as its failure, in a few words (the class page counts these).
std::string failureOf(const StageRecord& st) {
    if (st.status == Status::Missing) return "not handed in";
    if (unjudged(st.status))
        return std::string(statusName(st.status)) + ": " + st.message.substr(0, 120);
    for (const RowRecord& row : st.rows)
        if (row.status() == Status::Fail) {
            std::string outcome =
                row.result.expectation.entry ? row.result.expectation.entry->outcome : "";
            return "FAIL at '" + row.result.lesson + "' (expected " + outcome + ")";
        }
    return "";
}

// The copy flags of the class (course/copy_flags.h), one row per student and file: for the
// instructor to look at, never a score, never on a student's page.
std::string copyFlagsTable(const std::vector<StudentRecord>& records,
                           const std::vector<std::string>& pages) {
    std::ostringstream rows;
    for (std::size_t k = 0; k < records.size(); ++k)
        for (const std::string& f : records[k].flags)
            rows << "<tr><td><a href=\"" << esc(pages[k]) << "\">"
                 << esc(escapedName(records[k].student)) << "</a></td><td class=\"msg\">" << esc(f)
                 << "</td></tr>\n";
    if (rows.str().empty()) return "";
    return "<h2>Possible copies (for the instructor: not a score)</h2>\n"
           "<table><tr><th>student</th><th>file and what it equals</th></tr>\n" +
           rows.str() + "</table>\n";
}

}  // namespace

std::string classPage(const std::string& assignment, const std::vector<StudentRecord>& records,
                      const std::vector<std::string>& pages,
                      const std::vector<std::string>& skipped) {
    std::ostringstream h;
    h << "<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>" << esc(assignment)
      << ": the class</title>" << kStyle << "</head><body>\n<h1>" << esc(assignment) << "</h1>\n";
    std::vector<std::string> stages;
    if (!records.empty())
        for (const StageRecord& st : records.front().stages)
            stages.push_back(st.stage + "/" + st.tree);
    h << "<p>" << records.size() << " students</p>\n<table><tr><th>student</th>";
    for (const auto& s : stages) h << "<th>" << esc(s) << "</th>";
    h << "<th>total</th></tr>\n";
    std::vector<std::map<std::string, int>> failures(stages.size());
    for (std::size_t k = 0; k < records.size(); ++k) {
        const StudentRecord& r = records[k];
        h << "<tr><td><a href=\"" << esc(pages[k]) << "\">" << esc(escapedName(r.student)) << "</a>"
          << (r.roster ? " " + esc(r.roster->name) : std::string()) << "</td>";
        std::size_t i = 0;
        for (const StageRecord& st : r.stages) {
            double p = st.points, m = st.maxPoints;
            const bool scored = !unjudged(st.status);
            std::string cls = st.status == Status::NotGraded ? "NOT"
                              : !scored                      ? statusName(st.status)
                              : p >= m                       ? "full"
                              : p <= 0                       ? "none"
                                                             : "part";
            h << "<td class=\"" << esc(cls) << "\">"
              << (scored ? numText(p) : esc(statusName(st.status))) << "</td>";
            std::string f = failureOf(st);
            if (!f.empty() && i < failures.size()) ++failures[i][f];
            ++i;
        }
        h << "<td>" << (r.graded() ? numText(r.score) + " / " + numText(r.maxScore) : "not graded")
          << "</td></tr>\n";
    }
    h << "</table>\n<h2>Most common failure per "
         "stage</h2>\n<table><tr><th>stage</th><th>failure</th><th>students</th></tr>\n";
    for (std::size_t i = 0; i < stages.size(); ++i) {
        std::string best;
        int count = 0;
        for (const auto& [f, n] : failures[i])
            if (n > count) {
                best = f;
                count = n;
            }
        h << "<tr><td>" << esc(stages[i]) << "</td><td class=\"msg\">"
          << (count ? esc(best) : "none") << "</td><td>" << count << "</td></tr>\n";
    }
    h << "</table>\n";
    // The source rules' findings (possible gaming, a method not written): for the instructor,
    // never a score by themselves, never on a student's page.
    std::ostringstream notes;
    for (std::size_t k = 0; k < records.size(); ++k)
        for (const StageRecord& st : records[k].stages) {
            std::set<std::string> seen;
            for (const RowRecord& row : st.rows)
                for (const std::string& n : row.result.sourceNotes)
                    if (seen.insert(n).second)
                        notes << "<tr><td><a href=\"" << esc(pages[k]) << "\">"
                              << esc(escapedName(records[k].student)) << "</a></td><td>"
                              << esc(st.stage + "/" + st.tree) << "</td><td class=\"msg\">"
                              << esc(n) << "</td></tr>\n";
        }
    if (!notes.str().empty())
        h << "<h2>Notes from the source rules (for the instructor: not a score)</h2>\n"
             "<table><tr><th>student</th><th>stage</th><th>note</th></tr>\n"
          << notes.str() << "</table>\n";
    h << copyFlagsTable(records, pages);
    if (!skipped.empty()) {
        h << "<h2>Left out of the class folder (not hand-ins)</h2>\n<ul>\n";
        for (const std::string& s : skipped) h << "<li>" << esc(s) << "</li>\n";
        h << "</ul>\n";
    }
    h << "</body></html>\n";
    return h.str();
}

}  // namespace sl
