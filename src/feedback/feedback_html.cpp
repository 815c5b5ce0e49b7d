#include "feedback/feedback_html.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

#include "feedback/html_text.h"
#include "feedback/student_summary.h"
#include "grade/judge.h"
#include "io/files.h"
#include "metrics/figures.h"
#include "stages/registry.h"

namespace sl {

using nlohmann::json;

std::string base64(const std::string& bytes) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        unsigned v = (unsigned char)bytes[i] << 16 | (unsigned char)bytes[i + 1] << 8 |
                     (unsigned char)bytes[i + 2];
        for (int k = 18; k >= 0; k -= 6) out += table[(v >> k) & 63];
    }
    if (i < bytes.size()) {
        unsigned v = (unsigned char)bytes[i] << 16;
        if (i + 1 < bytes.size()) v |= (unsigned char)bytes[i + 1] << 8;
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? table[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

namespace {

// An image beside the diff (X.png; X.render.png, X.truth.png) as a data: URI.
std::string imageUri(const CheckResult& row, const std::string& kind) {
    if (row.diffFile.empty()) return "";
    std::string path = row.diffFile;
    if (!kind.empty()) path = path.substr(0, path.size() - 4) + "." + kind + ".png";
    std::string bytes;
    if (!readRegularFile(path, 8u << 20, bytes).empty()) return "";
    return "data:image/png;base64," + base64(bytes);
}

// A number as the judge's message writes it (three significant digits): the page and the
// message agree on what was measured.
std::string figureNumber(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", v);
    return text;
}

// One bound a figure missed, in plain words, from the record's reasons (grade/judge.h): what
// the figure measures and its unit from the figure table, its value and the bound as held.
std::string reasonInWords(const FigureReason& f) {
    const FigureInfo* info = findFigure(f.figure);
    std::string what = info ? info->words : f.figure;
    if (!f.changeFrom.empty())  // a drawn pair's change (judgeResponse)
        what =
            "the change in " + what + " from the row before (at " + f.changeFrom + ") to this one";
    const std::string unit = info ? std::string(" ") + info->unit : "";
    if (std::isnan(f.value)) return what + " was not measured";
    return what + " is " + figureNumber(f.value) + unit + ", and should be " +
           (f.side == FigureReason::Side::AtLeast ? "at least " : "at most ") +
           figureNumber(f.bound) + unit;
}

}  // namespace

std::string plainWords(const RowRecord& rr) {
    const CheckResult& row = rr.result;
    std::ostringstream out;
    switch (row.status) {
        case Status::Missing:
            return "This stage was not in your hand-in, so it could not be graded.";
        case Status::NotGraded:
            return "This check could not be run on the grading machine. That is not your "
                   "submission's fault; it will be graded again.";
        case Status::Timeout:
            return "Your shader could not be run: " + row.message + ". " + kTimeoutCause +
                   " Fix this first; the stage gets no points until it runs.";
        case Status::Error:
        case Status::Crash:
            return "Your shader could not be run: " + row.message +
                   ". Fix this first; the stage gets no points until it runs.";
        default:
            break;
    }
    if (row.expectation.entry)
        out << "This setting should show: " << row.expectation.entry->outcome << ". ";
    const Accuracy& f = row.figures;
    if (!std::isnan(f.falseShadowPct))
        out << numText(f.falseShadowPct, 1)
            << " % of the surfaces the light reaches are drawn in shadow; ";
    if (!std::isnan(f.falseLitPct))
        out << numText(f.falseLitPct, 1) << " % of the true shadows are drawn lit; ";
    if (!std::isnan(f.edgeP95Px))
        out << "shadow edges are within " << numText(f.edgeP95Px, 1)
            << " px of the truth for 95 % of them. ";
    if (!std::isnan(f.mirrorIdPct))
        out << numText(f.mirrorIdPct, 1) << " % of the mirror shows the right object. ";
    if (earnsPoints(row.status)) {
        out << "That is what this check expects.";
        return out.str();
    }
    out << "That is not what this check expects";
    // The failing figures as the record holds them; a row without reasons (a record kept before
    // they were, or no bound held) has only its message to say why, shown as it is.
    int failed = 0;
    for (const FigureReason& reason : row.reasons)
        if (!reason.passed) out << (failed++ == 0 ? ": " : "; ") << reasonInWords(reason);
    if (failed == 0 && !row.message.empty()) out << ": " << row.message;
    out << ".";
    return out.str();
}

namespace {

// The three pictures of a row's check, side by side, with the legend of its difference picture
// (the mirror's is its difference from our exact stencil reflection).
std::string picturesOf(const CheckResult& row) {
    const bool mirror = stageNeedsMirror(row.stage);
    const std::pair<const char*, std::string> pictures[] = {
        {"your picture", imageUri(row, "render")},
        {mirror ? "the exact reflection (stencil method, our shaders)" : "the truth (ray traced)",
         imageUri(row, "truth")},
        {mirror ? "the difference inside the mirror" : "the difference", imageUri(row, "")}};
    std::ostringstream h;
    h << "<p>Pictures of the check <b>" << esc(row.view) << " " << esc(row.lesson)
      << "</b>:</p>\n<div class=\"pics\">";
    for (const auto& [caption, uri] : pictures)
        if (!uri.empty())
            h << "<figure><img alt=\"" << caption << "\" src=\"" << uri << "\"><figcaption>"
              << caption << "</figcaption></figure>";
    h << "</div>\n<p class=\"legend\">";
    if (mirror)
        h << "<span style=\"background:#d22\">red</span>your mirror differs from the exact "
             "reflection (the brighter, the larger) <span style=\"background:#000\">black</span>"
             "agrees <span style=\"background:#888\">grey</span>outside the mirror</p>\n";
    else
        h << "<span style=\"background:#d22\">red</span>drawn in shadow, truly lit "
             "<span style=\"background:#22d\">blue</span>drawn lit, truly in shadow "
             "<span style=\"background:#888\">grey</span>agrees with the truth</p>\n";
    return h.str();
}

// The late policy's line: when the hand-in came and what it cost.
std::string lateLine(const LateRecord& late, const StudentRecord& r) {
    std::ostringstream h;
    h << "<p>Handed in " << esc(late.handedIn) << " (from " << esc(late.source) << "): ";
    if (late.days == 0)
        h << "on time.";
    else
        h << numText(late.minutes / 60.0, 1) << " hours late, " << late.days
          << (late.days == 1 ? " day" : " days")
          << " charged by the late policy: " << numText(late.penalty) << " points off"
          << (late.capped ? " (the policy's cap: no more is taken however late)" : "")
          << (hidesPoints(r) ? "."
                             : ", " + numText(r.total()) + " of " + numText(r.maxScore) +
                                   " points after the penalty.");
    h << "</p>\n";
    return h.str();
}

// The head line's points: the total (StudentRecord::total(), as the class page and the
// gradebook show it), and what took it from the graded points when anything did. Not while
// checks are hidden from the student: the total less the stages they see would tell them.
std::string totalLine(const StudentRecord& r) {
    if (!r.graded())
        return "not graded yet (the grading machine could not run every check; it will be "
               "graded again)";
    if (hidesPoints(r))
        return "your total is in your course's gradebook once your instructor releases it (some "
               "checks are graded but hidden: the total would tell their results)";
    std::string line = "<span class=\"total\">" + numText(r.total()) + " of " +
                       numText(r.maxScore) + " points</span>";
    const bool late = r.late && r.late->days > 0;
    if (!late && r.adjustments.empty()) return line;
    line += " (graded " + numText(r.score);
    if (late) line += ", late policy -" + numText(r.late->penalty);
    if (!r.adjustments.empty())
        line += ", adjusted " + std::string(r.adjusted() >= 0 ? "+" : "") + numText(r.adjusted());
    return line + ")";
}

// The source rules' notes on a stage's files (in the student's own file names, grade/record.h),
// once each: what the shader's text does that the pictures may not show.
std::string sourceNotesOf(const StageRecord& st) {
    std::set<std::string> seen;
    std::ostringstream items;
    for (const RowRecord& row : st.rows)
        if (seenByStudent(st, row))
            for (const std::string& n : row.result.sourceNotes)
                if (seen.insert(n).second) items << "<li>" << esc(n) << "</li>\n";
    if (items.str().empty()) return "";
    return "<p>Notes on your source (for you and your instructor to read; they cost no "
           "points by themselves):</p>\n<ul class=\"notes\">\n" +
           items.str() + "</ul>\n";
}

// The student's own check report against the grade (grade/own_check.h), counting only rows whose
// grade they see, and the first few where their machine said otherwise. Nothing when it was not
// compared: the record's notes say why.
std::string ownCheckLine(const OwnCheck& o) {
    constexpr int kNamed = 3;
    if (!o.problem.empty() || o.seenCompared == 0) return "";
    const std::string machine = o.machine.empty() ? o.backend : o.machine;
    std::ostringstream h;
    h << "<p class=\"own-check\">Your own check (" << esc(o.file)
      << (machine.empty() ? "" : ", on " + esc(machine)) << ") agreed with the grade on "
      << o.seenAgreed << " of " << o.seenCompared << (o.seenCompared == 1 ? " row" : " rows");
    int named = 0;
    for (const OwnCheckRow& d : o.disagreements) {
        if (!d.seen || named == kNamed) continue;
        h << (named++ ? "; " : ": ") << "it said " << esc(statusName(d.home))
          << " where the grade says " << esc(statusName(d.grade)) << " on " << esc(d.row);
    }
    const int more = o.seenCompared - o.seenAgreed - named;
    if (more > 0) h << "; and " << more << " more";
    h << ".";
    if (o.seenAgreed < o.seenCompared)
        h << " The grade is what counts: every row was rendered again here. A row your machine "
             "judged otherwise may be a driver difference; ask your instructor.";
    h << "</p>\n";
    return h.str();
}

std::string pointsOf(double points, double max, Status status) {
    return status == Status::NotGraded ? "not graded"
                                       : numText(points) + " of " + numText(max) + " points";
}

}  // namespace

std::string studentPage(const StudentRecord& record) {
    std::ostringstream h;
    h << "<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>"
      << esc(escapedName(record.student)) << ": " << esc(record.assignment) << "</title>" << kStyle
      << "</head><body>\n";
    h << "<h1>" << esc(record.assignment) << "</h1>\n<p><b>" << esc(escapedName(record.student))
      << "</b>"
      << (record.roster ? " (" + esc(record.roster->name) + ", " + esc(record.roster->id) + ")"
                        : std::string())
      << ": " << totalLine(record) << "</p>\n";
    // Nothing is charged on a student not graded: the late policy applies to a score.
    if (record.late && record.graded()) h << lateLine(*record.late, record);
    for (const Adjustment& a : record.adjustments)
        h << "<p>Adjusted by your teaching staff: " << (a.points >= 0 ? "+" : "")
          << numText(a.points) << " points on " << esc(a.stage) << ": " << esc(a.reason)
          << "</p>\n";
    if (!record.error.empty()) h << "<p class=\"ERROR\">" << esc(record.error) << "</p>\n";
    for (const std::string& n : record.notes) h << "<p>Note: " << esc(n) << "</p>\n";
    if (record.ownCheck) h << ownCheckLine(*record.ownCheck);
    h << stagesSummary(record);
    int hiddenStages = 0;  // graded, but neither named nor shown: the student sees no result
    for (const StageRecord& st : record.stages) {
        if (st.visibility == "hidden") {
            ++hiddenStages;
            continue;
        }
        std::string id = st.stage + "/" + st.tree;
        // The rows this student sees: a hidden row's points or status would give it away.
        const SeenStage seen = seenStage(st);
        std::string status = statusName(seen.status);
        h << "<h2 id=\"" << esc(id) << "\">" << esc(id) << ": "
          << pointsOf(seen.points, seen.maxPoints, seen.status) << " <span class=\"" << esc(status)
          << "\">" << esc(status) << "</span></h2>\n<p>"
          << esc(seen.status == Status::NotGraded
                     ? "The grading machine could not run this stage. That is not your "
                       "submission's fault; it will be graded again."
                     : st.message)
          << "</p>\n";
        const RowRecord* shown = nullptr;
        h << "<table><tr><th>view</th><th>setting</th><th>verdict</th><th>points</th><th>in plain "
             "words</th></tr>\n";
        for (const RowRecord& row : st.rows) {
            if (!seenByStudent(st, row)) continue;
            const Status v = row.status();
            if (!shown || (shown->status() == Status::Pass && v != Status::Pass &&
                           !row.result.diffFile.empty()))
                shown = &row;
            h << "<tr><td>" << esc(row.result.view) << "</td><td>" << esc(row.result.lesson)
              << "</td><td class=\"" << esc(statusName(v)) << "\">" << esc(statusName(v))
              << "</td><td>"
              << (isScored(v) ? numText(row.points) + " / " + numText(row.maxPoints) : "-")
              << "</td><td class=\"msg\">" << esc(plainWords(row)) << "</td></tr>\n";
        }
        h << "</table>\n";
        if (seen.hidden)  // how many is not said: with the total it would tell their verdicts
            h << "<p>More checks of this stage are graded but hidden.</p>\n";
        h << sourceNotesOf(st);
        if (shown && !shown->result.diffFile.empty())
            h << picturesOf(shown->result) << lessonCaption(*shown);
    }
    if (hiddenStages)
        h << "<p>" << hiddenStages << (hiddenStages == 1 ? " more stage is" : " more stages are")
          << " graded but hidden.</p>\n";
    h << "</body></html>\n";
    return h.str();
}

}  // namespace sl
