#include "feedback/class_page.h"

#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "feedback/html_text.h"
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

// The possible copies (class/copy_pairs.h), for the instructor to look at, never a score, never
// on a student's page: one row per pair at or above the threshold, ranked by the share of their
// written due code in common; the pairs below it counted (short natural code is shared by
// honest students); the files equal to the published solution, one row per student and file.
std::string copiesTables(const ClassCopies& copies, const std::vector<StudentRecord>& records,
                         const std::vector<std::string>& pages) {
    std::map<std::string, std::string> pageOf;
    for (std::size_t k = 0; k < records.size() && k < pages.size(); ++k)
        pageOf[records[k].student] = pages[k];
    auto who = [&](const std::string& name) {
        auto it = pageOf.find(name);
        return it == pageOf.end()
                   ? esc(escapedName(name))
                   : "<a href=\"" + esc(it->second) + "\">" + esc(escapedName(name)) + "</a>";
    };
    std::ostringstream pairs, solution;
    std::size_t below = 0;
    for (const CopyPair& p : copies.pairs) {
        if (p.share < kCopyShareFlagged) {
            ++below;
            continue;
        }
        std::string files;
        for (const std::string& f : p.files) files += (files.empty() ? "" : ", ") + f;
        pairs << "<tr><td>" << who(p.a) << " and " << who(p.b) << "</td><td class=\"share\">"
              << numText(100 * p.share, 0) << " %</td><td>" << p.files.size() << " ("
              << p.commonTokens << " written tokens)</td><td class=\"msg\">" << esc(files)
              << "</td></tr>\n";
    }
    for (const CopyFlag& f : copies.solution)
        solution << "<tr><td>" << who(f.student) << "</td><td class=\"msg\">" << esc(f.file)
                 << "</td></tr>\n";
    if (pairs.str().empty() && solution.str().empty() && below == 0) return "";
    std::ostringstream h;
    h << "<h2>Possible copies (for the instructor: not a score)</h2>\n";
    if (!pairs.str().empty())
        h << "<table class=\"pairs\"><tr><th>pair</th><th>their written due code in common</th>"
             "<th>files the same</th><th>which</th></tr>\n"
          << pairs.str() << "</table>\n";
    if (below)
        h << "<p>" << below << (below == 1 ? " more pair has" : " more pairs have")
          << " some due code the same, under " << numText(100 * kCopyShareFlagged, 0)
          << " % of what they wrote (short code is often written the same by honest students): "
             "not flagged.</p>\n";
    if (!solution.str().empty())
        h << "<table><tr><th>student</th><th>the same as the published solution</th></tr>\n"
          << solution.str() << "</table>\n";
    return h.str();
}

// A student's late penalty, adjustments and total (after both), as cells of the class table.
std::string totalCells(const StudentRecord& r) {
    if (!r.graded()) return "<td></td><td></td><td class=\"total\">not graded</td>";
    std::string late, adjusted;
    if (r.late && r.late->days > 0)
        late = "-" + numText(r.late->penalty) + " (" + std::to_string(r.late->days) +
               (r.late->days == 1 ? " day" : " days") + (r.late->capped ? ", capped" : "") + ")";
    if (!r.adjustments.empty()) {
        const double a = r.adjusted();
        adjusted = (a >= 0 ? "+" : "") + numText(a);
    }
    return "<td>" + esc(late) + "</td><td>" + esc(adjusted) + "</td><td class=\"total\">" +
           numText(r.total()) + " / " + numText(r.maxScore) + "</td>";
}

// The students' own check reports against their grades (grade/own_check.h), for the instructor:
// who handed one in, whose disagreed (how many rows, on what machine, the first few) and whose
// could not be compared. Never a score; a row that disagrees on an honest report points at a
// driver difference.
std::string ownChecksTable(const std::vector<StudentRecord>& records,
                           const std::vector<std::string>& pages) {
    constexpr std::size_t kNamed = 3;
    std::ostringstream rows;
    int handedIn = 0, allAgreed = 0;
    for (std::size_t k = 0; k < records.size(); ++k) {
        const std::optional<OwnCheck>& o = records[k].ownCheck;
        if (!o) continue;
        ++handedIn;
        if (o->problem.empty() && o->disagreed == 0) {
            ++allAgreed;
            continue;
        }
        rows << "<tr><td><a href=\"" << esc(pages[k]) << "\">"
             << esc(escapedName(records[k].student)) << "</a></td><td>"
             << esc(o->machine.empty() ? o->backend : o->machine) << "</td>";
        if (!o->problem.empty()) {
            rows << "<td></td><td class=\"msg\">not compared: " << esc(o->problem)
                 << "</td></tr>\n";
            continue;
        }
        rows << "<td>" << o->disagreed << " of " << o->compared << "</td><td class=\"msg\">";
        for (std::size_t i = 0; i < o->disagreements.size() && i < kNamed; ++i) {
            const OwnCheckRow& d = o->disagreements[i];
            rows << (i ? "; " : "") << esc(d.row) << ": " << esc(statusName(d.home)) << " at home, "
                 << esc(statusName(d.grade)) << " graded";
        }
        if (o->disagreed > int(kNamed)) rows << "; and " << o->disagreed - int(kNamed) << " more";
        rows << "</td></tr>\n";
    }
    if (handedIn == 0) return "";
    std::ostringstream h;
    h << "<h2>Own check reports (for the instructor: not a score)</h2>\n<p>" << handedIn
      << (handedIn == 1 ? " student" : " students") << " handed in their own check report; "
      << allAgreed << " agreed with the grade on every row compared.</p>\n";
    if (!rows.str().empty())
        h << "<table class=\"own-checks\"><tr><th>student</th><th>their machine</th><th>rows "
             "that disagree</th><th>first rows (their verdict, the grade's)</th></tr>\n"
          << rows.str() << "</table>\n";
    return h.str();
}

}  // namespace

std::string classPage(const std::string& assignment, const std::vector<StudentRecord>& records,
                      const std::vector<std::string>& pages,
                      const std::vector<std::string>& skipped, const ClassCopies& copies) {
    std::ostringstream h;
    h << "<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>" << esc(assignment)
      << ": the class</title>" << kStyle << "</head><body>\n<h1>" << esc(assignment) << "</h1>\n";
    std::vector<std::string> stages;
    if (!records.empty())
        for (const StageRecord& st : records.front().stages)
            stages.push_back(st.stage + "/" + st.tree);
    h << "<p>" << records.size() << " students</p>\n<table><tr><th>student</th>";
    for (const auto& s : stages) h << "<th>" << esc(s) << "</th>";
    // The total is StudentRecord::total(), as in grades.csv, the exports and the student's page;
    // what took it from the graded points is beside it.
    h << "<th>late</th><th>adjusted</th><th>total</th></tr>\n";
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
        h << totalCells(r) << "</tr>\n";
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
    // never a score by themselves; the student's page shows their own (feedback_html.h).
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
    h << ownChecksTable(records, pages);
    h << copiesTables(copies, records, pages);
    if (!skipped.empty()) {
        h << "<h2>Left out of the class folder (not hand-ins)</h2>\n<ul>\n";
        for (const std::string& s : skipped) h << "<li>" << esc(s) << "</li>\n";
        h << "</ul>\n";
    }
    h << "</body></html>\n";
    return h.str();
}

}  // namespace sl
