#include "bench/bench_report.h"

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "bench/bench_output.h"
#include "io/files.h"
#include "io/usage_error.h"
#include "metrics/figures.h"
#include "metrics/figures_json.h"
#include "metrics/pareto.h"
#include "stages/registry.h"

namespace sl {

namespace {

// The configuration, its times and its ratio to phong; then the accuracy columns (kColumns).
const std::vector<std::string> kRunColumns = {"group",
                                              "series",
                                              "stage",
                                              "tree",
                                              "scene",
                                              "width",
                                              "height",
                                              "settings",
                                              "map_size",
                                              "light",
                                              "frames",
                                              "frame_ms",
                                              "frame_iqr_ms",
                                              "frame_min_ms",
                                              "frame_max_ms",
                                              "shadow_ms",
                                              "lit_ms",
                                              "mirror_ms",
                                              "map_renders",
                                              "ratio_to_phong",
                                              "ratio_p25",
                                              "ratio_p75",
                                              "ratio_iqr",
                                              "ratio_blocks",
                                              "ratio_trusted",
                                              "instructions_per_frame",
                                              "instructions_ratio_to_phong"};

// The accuracy columns after kRunColumns: the shadow figures (metrics/figures.h), the charts'
// error %, the mirror's figures.
std::vector<const FigureInfo*> figuresOf(FigureKind kind) {
    std::vector<const FigureInfo*> out;
    for (const FigureInfo& f : figureTable())
        if (f.kind == kind) out.push_back(&f);
    return out;
}
const std::vector<std::string> kColumns = [] {
    std::vector<std::string> columns = kRunColumns;
    for (const FigureInfo* f : figuresOf(FigureKind::Shadow)) columns.push_back(f->name);
    columns.push_back("error_pct");
    for (const FigureInfo* f : figuresOf(FigureKind::Mirror)) columns.push_back(f->name);
    return columns;
}();

// The map size a configuration used: its own setting or the stage's default; NaN without a map.
double mapSize(const BenchConfig& c) {
    for (const auto& [name, value] : c.sets)
        if (name == "map-size") return std::stod(value);
    const StageInfo* info = findStage(c.stage);
    for (const ParamSpec& p : info->params)
        if (p.name == "map-size") return p.defaultValue;
    return NAN;
}

// A target's words with "{ratio}" replaced by the measured ratio (two decimals).
std::string replaceRatio(std::string words, double ratio) {
    char value[32];
    std::snprintf(value, sizeof value, "%.2f", ratio);
    std::size_t at = words.find("{ratio}");
    if (at != std::string::npos) words.replace(at, 7, value);
    return words;
}

std::string family(const std::string& series) {
    return series.substr(0, series.find('/'));
}

struct Row {
    const Measured* m;
    bool moving;
    RatioSummary ratio;
    const PassTimes& t() const { return moving ? m->moving : m->still; }
};

std::vector<std::string> cells(const Row& r) {
    const BenchConfig& c = r.m->config;
    const Accuracy& a = r.m->accuracy;
    const PassTimes& t = r.t();
    std::vector<std::string> cell = {
        c.group,
        c.series,
        c.stage,
        treeName(c.tree),
        r.m->scene,
        std::to_string(c.width),
        std::to_string(c.height),
        c.setsText(),
        num(mapSize(c)),
        r.moving ? "moving" : "still",
        std::to_string(t.frame.count),
        num(t.frame.median),
        num(t.frame.iqr()),
        num(t.frame.min),
        num(t.frame.max),
        num(t.shadow.median),
        num(t.lit.median),
        num(t.mirror.median),
        std::to_string(t.mapRenders),
        num(r.ratio.median),
        num(r.ratio.p25),
        num(r.ratio.p75),
        num(r.ratio.iqr()),
        std::to_string(r.ratio.blocks),
        r.ratio.trusted() ? "yes" : "no",
        num(r.moving ? r.m->instructions.moving : r.m->instructions.still, 6),
        num(r.moving ? r.m->instructions.ratioMoving : r.m->instructions.ratioStill)};
    for (const FigureInfo* f : figuresOf(FigureKind::Shadow)) cell.push_back(num(a.*f->field));
    cell.push_back(num(a.errorPct));
    for (const FigureInfo* f : figuresOf(FigureKind::Mirror)) cell.push_back(num(a.*f->field));
    return cell;
}

nlohmann::json rowJson(const std::vector<std::string>& cell) {
    nlohmann::json j;
    for (std::size_t k = 0; k < kColumns.size(); ++k) {
        const std::string& v = cell[k];
        char* end = nullptr;
        double d = std::strtod(v.c_str(), &end);
        if (v == "na")
            j[kColumns[k]] = nullptr;
        else if (kColumns[k] == "ratio_trusted")
            j[kColumns[k]] = v == "yes";
        else if (!v.empty() && *end == '\0' && kColumns[k] != "settings")
            j[kColumns[k]] = d;
        else
            j[kColumns[k]] = v;
    }
    return j;
}

std::string chartScript(const std::string& machine, bool instructions) {
    std::ostringstream g;
    g << "# Regenerate the charts from the .dat files beside this script: gnuplot charts.gp\n"
      << "set terminal pngcairo size 960,640 font 'sans,10'\n"
      << "set key outside right top\nset grid\n"
      // gnuplot's default colours cycle after 8: more than 8 series (methods) would share one.
      << "set linetype 9 lc rgb '#8c564b'\nset linetype 10 lc rgb '#7f7f7f'\n"
      << "set linetype 11 lc rgb '#17becf'\nset linetype 12 lc rgb '#bcbd22'\n"
      << "set linetype cycle 12\n"
      << "machine = '" << machine << "'\n"
      << "set output 'error-vs-time.png.tmp'\n"
      << "set title \"Error against frame time (640x480, light moving every frame)\\n\".machine\n"
      << "set xlabel 'frame time, ms (median, bars: quartiles)'\nset ylabel 'error % (balanced "
         "false shadow / false "
         "lit; mirror: 100 - id agreement)'\n"
      << "set logscale xy\nset yrange [0.001:100]\nshown(y) = y < 0.001 ? 0.001 : y\n"
      << "set label 1 \"lines: each method's Pareto front; bars: frame-time quartiles; an error of "
         "0 is drawn at 0.001\" at "
         "graph 0.01, graph 0.03\n"
      // Log axes round out to whole decades; keep the data's own range with a margin instead.
      << "set autoscale xfix\nset offsets graph 0.04, graph 0.04, 0, 0\n"
      << "plot for [i=0:*] 'points.dat' index i using 1:(shown($2)):3:4 with xerrorbars pt 7 ps "
         "0.8 "
         "lc i+1 title columnheader(1), \\\n"
      << "     for [i=0:*] 'pareto.dat' index i using 1:(shown($2)) with lines lw 2 lc i+1 "
         "notitle\n"
      << (instructions
              ? "set output 'error-vs-instructions.png.tmp'\n"
                "set title \"Error against instructions per frame (640x480, light moving; "
                "callgrind, LP_NUM_THREADS=0)\\n\".machine noenhanced\n"
                "set xlabel 'instructions per frame, millions (deterministic)'\n"
                "set xtics (20, 30, 40, 50, 70, 100, 150, 200, 300)\n"
                "set label 1 \"lines: each method's Pareto front; an error of 0 is drawn at "
                "0.001\" at graph 0.01, graph 0.03\n"
                "plot for [i=0:*] 'instructions.dat' index i using 1:(shown($2)) with points pt 7 "
                "ps 0.8 lc i+1 title columnheader(1), \\\n"
                "     for [i=0:*] 'instructions-pareto.dat' index i using 1:(shown($2)) with lines "
                "lw 2 lc i+1 notitle\n"
                "set xtics autofreq\n"
              : "")
      << "unset logscale xy\nunset label 1\nset yrange [*:*]\n"
      << "set output 'time-vs-map-size.png.tmp'\n"
      << "set title \"Frame time against shadow-map size (640x480, map re-rendered every "
         "frame)\\n\".machine\n"
      << "set xlabel 'map size (texels per side)'\nset ylabel 'frame time, ms (median, bars: "
         "quartiles)'\n"
      << "set logscale x 2\nset logscale y\nset autoscale yfix\nset offsets 0, 0, graph 0.05, "
         "graph 0.05\n"
      << "set ytics add (2, 5, 20, 50, 200, 500)\n"
      << "plot for [i=0:*] 'map-size.dat' index i using 1:2:3:4 with yerrorlines pt 7 title "
         "columnheader(1)\n"
      << "unset logscale x\n"
      << "set output 'time-vs-window.png.tmp'\n"
      << "set title \"Frame time against window size (stage defaults, still light)\\n\".machine\n"
      << "set xlabel 'window (pixel count, log scale)'\nset ylabel 'frame time, ms (median, bars: "
         "quartiles)'\n"
      << "set logscale x\nset autoscale xfix\nset offsets graph 0.05, graph 0.05, graph 0.05, "
         "graph 0.05\n"
      << "set xtics ('320x240' 76.8, '640x480' 307.2, '1280x960' 1228.8)\n"
      << "plot for [i=0:*] 'window.dat' index i using 1:2:3:4 with yerrorlines pt 7 title "
         "columnheader(1)\n"
      << "set output\n"
      << "system('for f in *.png.tmp; do mv \"$f\" \"${f%.tmp}\"; done')\n";
    return g.str();
}

void writeOrThrow(const std::string& path, const std::string& text) {
    std::string err = writeTextFile(path, text);
    if (!err.empty()) throw UsageError("--out: " + err);
}

}  // namespace

std::string contextKey(const BenchConfig& c, const std::string& scene) {
    return treeName(c.tree) + std::string("/") + scene + "/" + std::to_string(c.width) + "x" +
           std::to_string(c.height);
}

BenchReport writeBenchReport(const std::string& dir, const std::string& machine,
                             const std::vector<Measured>& results) {
    Table table;
    table.columns = kColumns;
    nlohmann::json json = {{"machine", machine},
                           {"columns", kColumns},
                           {"rows", nlohmann::json::array()},
                           {"figures", figureTableJson()}};  // the columns' names, units and words
    std::vector<Row> rows;
    for (const Measured& m : results)
        for (bool moving : {false, true}) {
            Row r{&m, moving, m.ratios(moving)};
            rows.push_back(r);
            table.add(cells(r));
            json["rows"].push_back(rowJson(table.rows.back()));
        }
    // The equal-accuracy group on its own: per method, the cheapest configuration reaching the bar
    // (or the closest one, marked unreached) and its cost.
    json["equal_accuracy"] = nlohmann::json::array();
    for (const Measured& m : results) {
        if (m.config.group.rfind("equal-accuracy", 0) != 0) continue;
        auto number = [](double v) {
            return std::isnan(v) ? nlohmann::json(nullptr) : nlohmann::json(v);
        };
        json["equal_accuracy"].push_back(
            {{"method", m.config.series},
             {"reached", m.config.group == "equal-accuracy"},
             {"settings", m.config.setsText()},
             {"edge_p95_px", number(m.accuracy.edgeP95Px)},
             {"error_pct", number(m.accuracy.errorPct)},
             {"ratio_still", number(m.ratioStill.median)},
             {"ratio_still_iqr", number(m.ratioStill.iqr())},
             {"ratio_still_trusted", m.ratioStill.trusted()},
             {"ratio_moving", number(m.ratioMoving.median)},
             {"ratio_moving_iqr", number(m.ratioMoving.iqr())},
             {"ratio_moving_trusted", m.ratioMoving.trusted()},
             {"instructions_still", number(m.instructions.still)},
             {"instructions_moving", number(m.instructions.moving)},
             {"instructions_ratio_still", number(m.instructions.ratioStill)},
             {"instructions_ratio_moving", number(m.instructions.ratioMoving)}});
    }
    writeOrThrow(dir + "/bench.csv", table.csv());
    writeOrThrow(dir + "/bench.json",
                 json.dump(1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");

    // Chart data. Error against time: every 640x480 configuration, moving light, by method.
    std::map<std::string, Series> points;
    std::map<std::string, std::vector<CostError>> costs;
    std::map<std::string, Series> bySize, byWindow, byInstructions;
    std::map<std::string, std::vector<CostError>> instructionCosts;
    for (const Row& r : rows) {
        const BenchConfig& c = r.m->config;
        std::string fam = family(c.series);
        if (r.moving && c.width == 640 && c.height == 480 && !std::isnan(r.m->accuracy.errorPct)) {
            points[fam].title = fam;
            points[fam].xs.push_back(r.t().frame.median);
            points[fam].ys.push_back(r.m->accuracy.errorPct);
            points[fam].lo.push_back(r.t().frame.p25);
            points[fam].hi.push_back(r.t().frame.p75);
            costs[fam].push_back({r.t().frame.median, r.m->accuracy.errorPct, c.setsText()});
            double ir = r.m->instructions.moving;
            if (!std::isnan(ir)) {
                byInstructions[fam].title = fam;
                byInstructions[fam].xs.push_back(ir / 1e6);
                byInstructions[fam].ys.push_back(r.m->accuracy.errorPct);
                instructionCosts[fam].push_back({ir / 1e6, r.m->accuracy.errorPct, c.setsText()});
            }
        }
        if (r.moving && c.group == "map-size") {
            bySize[c.series].title = c.series + (c.tree == GlslTree::Legacy ? " (legacy)" : "");
            bySize[c.series].xs.push_back(mapSize(c));
            bySize[c.series].ys.push_back(r.t().frame.median);
            bySize[c.series].lo.push_back(r.t().frame.p25);
            bySize[c.series].hi.push_back(r.t().frame.p75);
        }
        // not a stage id: the scene "mirror"
        if (!r.moving && (c.group == "window" || c.group == "baseline") && r.m->scene != "mirror") {
            byWindow[c.series].title = c.series;
            byWindow[c.series].xs.push_back(c.width * c.height / 1000.0);
            byWindow[c.series].ys.push_back(r.t().frame.median);
            byWindow[c.series].lo.push_back(r.t().frame.p25);
            byWindow[c.series].hi.push_back(r.t().frame.p75);
        }
    }
    std::vector<Series> pointList, frontList, sizeList, windowList;
    for (auto& [fam, s] : points) {
        pointList.push_back(s);
        Series front{fam, {}, {}, {}, {}};
        for (std::size_t k : paretoFront(costs[fam])) {
            front.xs.push_back(costs[fam][k].cost);
            front.ys.push_back(costs[fam][k].error);
        }
        frontList.push_back(front);
    }
    std::vector<Series> instructionList, instructionFront;
    for (auto& [fam, s] : byInstructions) {
        instructionList.push_back(s);
        Series front{fam, {}, {}, {}, {}};
        for (std::size_t k : paretoFront(instructionCosts[fam])) {
            front.xs.push_back(instructionCosts[fam][k].cost);
            front.ys.push_back(instructionCosts[fam][k].error);
        }
        instructionFront.push_back(front);
    }
    for (auto& [name, s] : bySize) sizeList.push_back(s);
    for (auto& [name, s] : byWindow) {
        // Baseline rows may repeat a size (one per scene): keep the first of each.
        Series unique{s.title, {}, {}, {}, {}};
        for (std::size_t k = 0; k < s.xs.size(); ++k)
            if (std::find(unique.xs.begin(), unique.xs.end(), s.xs[k]) == unique.xs.end()) {
                unique.xs.push_back(s.xs[k]);
                unique.ys.push_back(s.ys[k]);
                unique.lo.push_back(s.lo[k]);
                unique.hi.push_back(s.hi[k]);
            }
        windowList.push_back(unique);
    }
    writeOrThrow(dir + "/points.dat", gnuplotBlocks(pointList));
    writeOrThrow(dir + "/pareto.dat", gnuplotBlocks(frontList));
    writeOrThrow(dir + "/map-size.dat", gnuplotBlocks(sizeList));
    writeOrThrow(dir + "/window.dat", gnuplotBlocks(windowList));
    bool instructions = !instructionList.empty();
    if (instructions) {
        writeOrThrow(dir + "/instructions.dat", gnuplotBlocks(instructionList));
        writeOrThrow(dir + "/instructions-pareto.dat", gnuplotBlocks(instructionFront));
    }

    BenchReport report;
    report.chartProblem = runGnuplot(dir, dir + "/charts.gp", chartScript(machine, instructions));

    // The summary: each stage at its defaults, 640x480, and the targets.
    std::ostringstream s;
    char line[256];
    s << "machine: " << machine << "\n";
    std::snprintf(line, sizeof line, "%-18s %-6s %10s %10s %16s %16s %9s\n", "stage (defaults)",
                  "tree", "still ms", "moving ms", "x phong still", "x phong moving", "error %");
    s << line;
    // A ratio with its interquartile range over the blocks; "?" marks one too spread to publish.
    auto ratioText = [](const RatioSummary& r) {
        char t[64];
        std::snprintf(t, sizeof t, "%.2f +-%.2f%s", r.median, r.iqr() / 2, r.trusted() ? "" : " ?");
        return std::string(t);
    };
    for (const Measured& m : results) {
        const BenchConfig& c = m.config;
        // not a stage id: the scene "mirror"
        bool defaults = (c.group == "window" || (c.group == "baseline" && m.scene != "mirror")) &&
                        c.width == 640 && c.height == 480;
        if (!defaults) continue;
        std::snprintf(line, sizeof line, "%-18s %-6s %10.2f %10.2f %16s %16s %9s\n",
                      c.stage.c_str(), treeName(c.tree), m.still.frame.median,
                      m.moving.frame.median, ratioText(m.ratioStill).c_str(),
                      ratioText(m.ratioMoving).c_str(), num(m.accuracy.errorPct, 3).c_str());
        s << line;
    }
    s << "ratios: median of per-block ratios to phong, +- half the interquartile range; '?': the "
         "spread is over "
      << num(100 * RatioSummary::kMaxRelativeSpread, 2)
      << " % of the ratio, not a figure to quote\n";
    bool counted = false;
    for (const Measured& m : results) counted = counted || !std::isnan(m.instructions.still);
    if (counted) {
        s << "instructions per frame (callgrind, LP_NUM_THREADS=0; repeatable where ms are not):\n";
        for (const Measured& m : results) {
            const BenchConfig& c = m.config;
            if (std::isnan(m.instructions.still) || c.group == "map-size") continue;
            std::snprintf(
                line, sizeof line, "%-18s %-6s %-7s still %8.2f M %5.2fx   moving %8.2f M %5.2fx\n",
                c.stage.c_str(), treeName(c.tree), m.scene.c_str(), m.instructions.still / 1e6,
                m.instructions.ratioStill, m.instructions.moving / 1e6, m.instructions.ratioMoving);
            s << line;
        }
    }
    bool equal = false;
    for (const Measured& m : results) {
        if (m.config.group.rfind("equal-accuracy", 0) != 0) continue;
        if (!equal)
            s << "cost at equal accuracy (edge p95 <= 2 px, error <= 0.1 %; cheapest by the "
                 "moving-light ratio):\n";
        equal = true;
        bool reached = m.config.group == "equal-accuracy";
        std::snprintf(
            line, sizeof line,
            "%-22s %-9s %-40s edge %6s px error %7s %%  x phong still %s moving %s%s\n",
            m.config.series.c_str(), reached ? "reached" : "NOT", m.config.setsText().c_str(),
            num(m.accuracy.edgeP95Px, 3).c_str(), num(m.accuracy.errorPct, 3).c_str(),
            ratioText(m.ratioStill).c_str(), ratioText(m.ratioMoving).c_str(),
            std::isnan(m.instructions.moving) ? ""
                                              : ("  instr " + num(m.instructions.ratioStill, 3) +
                                                 "x / " + num(m.instructions.ratioMoving, 3) + "x")
                                                    .c_str());
        s << line;
    }
    // A target is judged only on a ratio tight enough to quote.
    auto verdict = [](const RatioSummary& r, double target) {
        char t[64];
        std::snprintf(t, sizeof t, "not judged: spread %.0f %%", 100 * r.relativeSpread());
        if (!r.trusted()) return std::string(t);
        return std::string(r.median <= target ? "met" : "MISSED");
    };
    // The speed targets the stages declare on their series (BenchSeries::targets), on every row
    // of that series at 640 wide (and the target's map size).
    std::map<std::string, std::vector<const BenchTarget*>> targets;
    for (BenchGroup group :
         {BenchGroup::MapSize, BenchGroup::Format, BenchGroup::Mirror, BenchGroup::EqualAccuracy})
        for (const StageSeries& series : benchSeriesIn(group))
            for (const BenchTarget& t : series.series->targets)
                targets[series.series->name].push_back(&t);
    for (const Measured& m : results) {
        const BenchConfig& c = m.config;
        auto found = targets.find(c.series);
        if (found == targets.end() || c.width != 640) continue;
        for (const BenchTarget* t : found->second) {
            if (t->mapSize != 0 && mapSize(c) != t->mapSize) continue;
            std::string text = "target " + t->what;
            for (std::size_t k = 0; k < t->bounds.size(); ++k) {
                const BenchBound& b = t->bounds[k];
                std::snprintf(line, sizeof line, " (<= %.2f: %s)", b.atMost,
                              verdict(m.ratios(b.moving), b.atMost).c_str());
                text += (k ? "; " : "") + replaceRatio(b.words, m.ratio(b.moving)) + line;
            }
            s << text << "\n";
        }
    }
    report.summary = s.str();
    return report;
}

}  // namespace sl
