#include "grade/judge.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace sl {

namespace {

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", v);
    return text;
}

}  // namespace

bool FigureReason::operator==(const FigureReason& o) const {
    auto same = [](double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); };
    return figure == o.figure && same(value, o.value) && side == o.side && same(bound, o.bound) &&
           passed == o.passed && changeFrom == o.changeFrom;
}

const char* sideName(FigureReason::Side side) {
    return side == FigureReason::Side::AtLeast ? ">=" : "<=";
}

std::optional<FigureReason::Side> sideFromName(const std::string& name) {
    if (name == ">=") return FigureReason::Side::AtLeast;
    if (name == "<=") return FigureReason::Side::AtMost;
    return std::nullopt;
}

Judgement judge(const Expectation& e, const std::map<std::string, double>& figures) {
    std::string failed, unmeasured, held;
    std::vector<FigureReason> reasons;
    for (const Limit& l : e.limits) {
        auto it = figures.find(l.figure);
        double v = it == figures.end() ? NAN : it->second;
        // Each side the limit has, as it was held (a value not measured passes neither).
        if (!std::isnan(l.min))
            reasons.push_back({l.figure, v, FigureReason::Side::AtLeast, l.min, v >= l.min});
        if (!std::isnan(l.max))
            reasons.push_back({l.figure, v, FigureReason::Side::AtMost, l.max, v <= l.max});
        if (std::isnan(v)) {
            unmeasured += (unmeasured.empty() ? "" : ", ") + l.figure;
            continue;
        }
        bool ok = !(v < l.min) && !(v > l.max);  // a NaN bound compares false: no bound
        std::string& list = ok ? held : failed;
        list += (list.empty() ? "" : ", ") + l.figure + " " + number(v) + (ok ? " " : " not ") +
                l.bound();
    }
    if (!failed.empty())
        return {Status::Fail, "expected " + e.outcome + ", but " + failed, reasons};
    if (!unmeasured.empty()) return {Status::Skip, "not measured: " + unmeasured, reasons};
    return {Status::Pass, e.outcome + " as expected: " + held, reasons};
}

Judgement judgeDisplaced(const Expectation& e, const std::map<std::string, double>& theirs,
                         const DisplacedFigures* ours,
                         const std::map<std::string, double>* oursHere) {
    Expectation widened = e;
    bool wider = false;
    for (Limit& l : widened.limits) {
        std::optional<FigureRange> known;
        if (ours) {
            auto found = ours->find(l.figure);
            if (found != ours->end()) known = found->second;
        }
        if (oursHere) {
            auto here = oursHere->find(l.figure);
            if (here != oursHere->end() && !std::isnan(here->second)) {
                const double v = here->second;
                if (!known) known = FigureRange{v, v};
                known->lowest = std::min(known->lowest, v);
                known->highest = std::max(known->highest, v);
            }
        }
        if (!known) continue;
        const FigureRange& range = *known;
        // A quarter of the solution's figure: right for an error near 0 (specks, edge pixels),
        // far too much for a floor under a figure near its best (36 dB of PSNR, 99 % of mirror
        // ids: a quarter would let 27 dB and 74 % pass). So a floor is lowered only where the
        // solution itself comes within 0.5 of it (the acne a lesson asks for, which a displaced
        // view may show less of), never because the slack would reach under it.
        auto slack = [](double v) { return std::max(0.5, 0.25 * std::abs(v)); };
        const double high = range.highest + slack(range.highest);
        const double low = range.lowest - slack(range.lowest);
        if (!std::isnan(l.max) && high > l.max) l.max = high, wider = true;
        // A floor above 0 says the lesson's picture shows the figure (the inverted lesson's
        // false shadow): lowered, it stays above 0 where the solution shows any, at a quarter of
        // its lowest. At 0, a picture without it passed where ours showed little (a starter that
        // draws no shadow passed bias's inverted lesson in a displaced view where ours showed 0.2
        // %).
        const double floor = l.min > 0 ? std::max(low, 0.25 * range.lowest) : low;
        if (!std::isnan(l.min) && range.lowest < l.min + 0.5 && floor < l.min)
            l.min = floor, wider = true;
    }
    Judgement j = judge(widened, theirs);
    if (wider)
        j.message +=
            " [displaced view: bounds widened to the solution's figures in displaced views]";
    return j;
}

Judgement judgeDrawn(const DrawnRow& row, const std::string& drawnValues,
                     const std::map<std::string, double>& theirs,
                     const std::map<std::string, double>& ours) {
    Expectation againstOurs;
    againstOurs.stage = row.stage;
    againstOurs.outcome = "our shaders' picture";
    for (const DrawnTolerance& t : row.tolerances) {
        auto found = ours.find(t.figure);
        if (found == ours.end() || std::isnan(found->second)) continue;
        double v = found->second;
        againstOurs.limits.push_back(
            {t.figure, std::max(0.0, v / t.factor - t.abs), v * t.factor + t.abs});
    }
    if (againstOurs.limits.empty())
        return {Status::Skip, "our shaders measured none of " + row.label() + "'s figures", {}};
    Judgement j = judge(againstOurs, theirs);
    j.message += " [drawn " + drawnValues + ": held to our shaders at the same values]";
    return j;
}

namespace {

double figureOf(const std::map<std::string, double>& figures, const std::string& name) {
    auto found = figures.find(name);
    return found == figures.end() ? NAN : found->second;
}

}  // namespace

Judgement judgeResponse(const DrawnResponse& response, const std::string& from,
                        const std::map<std::string, double>& theirsFirst,
                        const std::map<std::string, double>& theirsSecond,
                        const std::map<std::string, double>& oursFirst,
                        const std::map<std::string, double>& oursSecond) {
    const DrawnTolerance& t = response.change;
    const std::string name = t.figure + " change from " + from;  // the message's words
    const double ours = figureOf(oursSecond, t.figure) - figureOf(oursFirst, t.figure);
    if (std::isnan(ours))
        return {Status::Skip, "our shaders measured no " + t.figure + " in both rows", {}};
    if (std::abs(ours) <= t.factor * t.abs)
        return {Status::Skip,
                "response to " + response.param + " not judged: ours changes by " + number(ours) +
                    " from " + from + ", within " + number(t.factor * t.abs) + " of none",
                {}};
    const double size = std::abs(ours), sign = ours < 0 ? -1 : 1;
    const double nearer = sign * (size / t.factor - t.abs),
                 farther = sign * (size * t.factor + t.abs);
    Expectation pair;
    pair.outcome = "our shaders' response to " + response.param;
    pair.limits.push_back({name, std::min(nearer, farther), std::max(nearer, farther)});
    const double theirs = figureOf(theirsSecond, t.figure) - figureOf(theirsFirst, t.figure);
    Judgement j = judge(pair, {{name, theirs}});
    for (FigureReason& f : j.reasons) f.figure = t.figure, f.changeFrom = from;
    return j;
}

Judgement withResponse(Judgement own, const Judgement& pair) {
    if (own.status == Status::Skip) return own;  // the row itself could not be judged
    if (pair.status == Status::Skip) {
        own.message += " [" + pair.message + "]";
        return own;
    }
    own.reasons.insert(own.reasons.end(), pair.reasons.begin(), pair.reasons.end());
    if (pair.status == Status::Fail) {
        own.message = pair.message + "; " + own.message;
        own.status = Status::Fail;
    } else {
        own.message += "; " + pair.message;
    }
    return own;
}

}  // namespace sl
