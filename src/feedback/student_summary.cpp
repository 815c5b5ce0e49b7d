#include "feedback/student_summary.h"

#include <cmath>
#include <sstream>

#include "feedback/html_text.h"
#include "metrics/figures.h"
#include "stages/expectations.h"

namespace sl {

const char* const kTimeoutCause =
    "A TIMEOUT is usually a loop that never ends (or runs far too many times): check that each "
    "loop's condition becomes false and that its counter changes.";

namespace {

// The first thing to fix in a stage, from its status and rows (never from its message's words).
std::string firstFix(const StageRecord& st, Status seen) {
    switch (seen) {
        case Status::Pass:
            return "nothing: every check shows the lesson";
        case Status::NotGraded:
            return "nothing yet: the grading machine could not run this stage (not your fault); "
                   "it will be graded again";
        case Status::Missing: {
            std::string files;
            for (const std::string& f : st.missingFiles) files += (files.empty() ? "" : ", ") + f;
            return "hand in " + (files.empty() ? std::string("this stage's files") : files);
        }
        case Status::Timeout:
            return std::string("make your shader finish: it ran past the time budget. ") +
                   kTimeoutCause;
        case Status::Error:
        case Status::Crash:
            return "make your shader run (it did not; the stage below says why): the stage gets "
                   "no points until it does";
        default:
            break;
    }
    for (const RowRecord& row : st.rows) {
        if (!seenByStudent(st, row) || earnsPoints(row.status())) continue;
        const CheckResult& r = row.result;
        std::string fix = "the check " + r.view + " " + r.lesson;
        if (r.expectation.entry) fix += ": it should show " + r.expectation.entry->outcome;
        return fix;
    }
    return "see the stage below";
}

}  // namespace

std::string stagesSummary(const StudentRecord& record) {
    std::ostringstream rows;
    for (const StageRecord& st : record.stages) {
        if (st.visibility == "hidden") continue;
        const std::string id = st.stage + "/" + st.tree;
        // The rows this student sees only: a hidden row's points or status would give it away.
        const SeenStage seen = seenStage(st);
        const std::string status = statusName(seen.status);
        rows << "<tr><td><a href=\"#" << esc(id) << "\">" << esc(id) << "</a></td><td class=\""
             << esc(status) << "\">" << esc(status) << "</td><td>"
             << (seen.status == Status::NotGraded
                     ? std::string("not graded")
                     : numText(seen.points) + " of " + numText(seen.maxPoints))
             << "</td><td class=\"msg\">" << esc(firstFix(st, seen.status)) << "</td></tr>\n";
    }
    if (rows.str().empty()) return "";
    return "<h2 id=\"summary\">Your stages at a glance</h2>\n<table class=\"summary\"><tr><th>"
           "stage</th><th>status</th><th>points</th><th>the first thing to fix</th></tr>\n" +
           rows.str() + "</table>\n";
}

std::string lessonCaption(const RowRecord& row) {
    const Expectation* e = row.result.expectation.entry;
    if (!e || !earnsPoints(row.status())) return "";
    // A lesson whose point is a fault asks for at least some error: a lower bound on a figure
    // that measures one (lower is better, in the figure table; the mirror's measure agreement).
    bool faultIsThePoint = false;
    for (const Limit& l : e->limits) {
        const FigureInfo* f = findFigure(l.figure);
        if (!std::isnan(l.min) && f && f->better == Better::Lower) faultIsThePoint = true;
    }
    if (!faultIsThePoint) return "";
    std::string caption = "These pictures show the lesson working: this setting should show " +
                          e->outcome +
                          ", and yours does. The fault you see (and the red or blue in the "
                          "difference) is the lesson's point, not a mistake of yours.";
    if (!e->look.empty()) caption += " What to look for: " + e->look;
    return "<p class=\"caption\">" + esc(caption) + "</p>\n";
}

}  // namespace sl
