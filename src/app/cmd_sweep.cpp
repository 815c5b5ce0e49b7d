// `shadowlab sweep AXIS [--out DIR]`: every shadow stage along one axis (light elevation, margin,
// polygon offset, the light's far/near ratio, map size), its error at each point, and where it
// breaks (error above a stated threshold); a CSV per axis, the break points and a chart.
#include <unistd.h>

#include <cmath>
#include <glm/gtc/constants.hpp>
#include <iostream>

#include "app/commands.h"
#include "bench/bench_output.h"
#include "bench/bench_run.h"
#include "io/files.h"
#include "io/usage_error.h"
#include "metrics/figures.h"
#include "metrics/pareto.h"
#include "stages/registry.h"

namespace sl {

namespace {

struct SweepArgs {
    std::string axis, out = "out/sweep", glsl = "core", size = "640x480", backend = "auto";
    double threshold = 5.0;
    bool quick = false;
};

struct Axis {
    std::string name, param, unit;  // param: the stage parameter it sets ("" = the light)
    std::vector<double> values;     // in the order the chart reads them
    std::vector<double> quickValues;
    bool logX = false;
};

const std::vector<Axis>& axes() {
    static const std::vector<Axis> all = {
        {"elevation",
         "",
         "degrees above the floor",
         {85, 75, 65, 55, 45, 35, 25, 20, 15, 10, 7, 5, 3, 2, 1},
         {85, 45, 15, 5, 1},
         false},
        {"margin",  // not a stage id: the axis, named after the parameter
         "margin",  // not a stage id: the parameter (stages that declare it are swept)
         "margin (window depth)",
         {0, 0.001, 0.002, 0.003, 0.004, 0.006, 0.008, 0.01, 0.015, 0.02, 0.03, 0.04, 0.05},
         {0, 0.004, 0.01, 0.05},
         false},
        {"offset",
         "offset-factor",
         "glPolygonOffset factor (units kept at each stage default)",
         {0, 0.5, 1, 2, 3, 4, 6, 8, 12, 16, 20, 30, 40},
         {0, 2, 20, 40},
         false},
        {"near-far",
         "far-near",
         "light far/near ratio",
         {2, 3, 5, 10, 20, 50, 100, 300, 1000, 3000, 10000},
         {2, 10, 1000, 10000},
         true},
        {"map-size",
         "map-size",
         "shadow-map size (texels per side)",
         {32, 64, 128, 256, 512, 1024, 2048, 4096},
         {64, 512},
         true},
    };
    return all;
}

const Axis& findAxis(const std::string& name) {
    std::vector<std::string> names;
    for (const Axis& a : axes()) {
        if (a.name == name) return a;
        names.push_back(a.name);
    }
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    std::string hint = closestMatch(name, names);
    throw UsageError("sweep: unknown axis '" + name + "'" +
                     (hint.empty() ? "" : " (did you mean '" + hint + "'?)") + "; axes: " + list);
}

// The light at `degrees` above the floor, as far from its target as the scene's and in the same
// compass direction.
glm::vec3 lightAtElevation(const glm::vec3& light, const glm::vec3& target, double degrees) {
    glm::vec3 d = light - target;
    float distance = glm::length(d);
    glm::vec3 flat(d.x, 0.0f, d.z);
    glm::vec3 compass = glm::length(flat) > 1e-6f ? glm::normalize(flat) : glm::vec3(1, 0, 0);
    float e = glm::radians(static_cast<float>(degrees));
    return target + distance * (std::cos(e) * compass + std::sin(e) * glm::vec3(0, 1, 0));
}

bool declares(const std::string& stage, const std::string& param) {
    for (const ParamSpec& p : findStage(stage)->params)
        if (p.name == param) return true;
    return false;
}

int runSweep(const SweepArgs& a) {
    const Axis& axis = findAxis(a.axis);
    GlslTree tree = a.glsl == "core" ? GlslTree::Core
                    : a.glsl == "legacy"
                        ? GlslTree::Legacy
                        : throw UsageError("--glsl: '" + a.glsl + "' is not one of core, legacy");
    CommonOptions sizeOnly;
    sizeOnly.size = a.size;
    RenderRequest sized = toRequest(sizeOnly);
    if (!(a.threshold > 0 && a.threshold < 100))
        throw UsageError("--threshold: must be a percentage between 0 and 100");
    makeOutputDir(a.out);
    const std::vector<double>& values = a.quick ? axis.quickValues : axis.values;

    std::vector<std::string> stages;
    for (const auto& s : stageRegistry())
        if (s.id != lightingStage().id && !s.needsMirror &&
            (axis.param.empty() || declares(s.id, axis.param)))
            stages.push_back(s.id);

    BenchRig rig(toBackend(a.backend));
    Table points, breaks;
    // The shadow figures (metrics/figures.h) and the charts' error %.
    points.columns = {"axis", "stage", "tree", "value"};
    for (const std::string& name : figureNamesOf(FigureKind::Shadow))
        points.columns.push_back(name);
    points.columns.push_back("error_pct");
    breaks.columns = {"axis",       "stage",          "tree",        "threshold_pct",
                      "best_value", "best_error_pct", "works",       "works_from",
                      "works_to",   "breaks_before",  "breaks_after"};
    std::vector<Series> chart, edges;
    bool tty = isatty(STDERR_FILENO);
    std::size_t done = 0, total = stages.size() * values.size();
    std::string machine;
    std::cout << "sweep " << axis.name << " (" << axis.unit << "), " << sized.width << "x"
              << sized.height << ", threshold " << a.threshold << " % balanced error\n";
    for (const std::string& stage : stages) {
        BenchConfig c;
        c.stage = stage;
        c.tree = findStage(stage)->legacyOnly ? GlslTree::Legacy : tree;
        c.width = sized.width;
        c.height = sized.height;
        Series line{
            stage + (c.tree == GlslTree::Legacy && tree == GlslTree::Core ? " (legacy)" : ""),
            {},
            {},
            {},
            {}};
        Series edge{line.title, {}, {}, {}, {}};
        for (double v : values) {
            BenchConfig at = c;
            std::optional<glm::vec3> light;
            if (axis.param.empty()) {
                rig.prepare(c);  // the scene's light, to start from
                light = lightAtElevation(rig.renderer().scene().light.position,
                                         rig.renderer().scene().light.target, v);
            } else {
                at.sets = {{axis.param, num(v, 8)}};
            }
            rig.prepare(at, light);
            Accuracy acc = rig.accuracy();
            std::vector<std::string> row = {axis.name, stage, treeName(c.tree), num(v, 8)};
            for (const FigureInfo& f : figureTable())
                if (f.kind == FigureKind::Shadow) row.push_back(num(acc.*f.field));
            row.push_back(num(acc.errorPct));
            points.add(row);
            line.xs.push_back(v);
            line.ys.push_back(acc.errorPct);
            edge.xs.push_back(v);
            edge.ys.push_back(acc.edgeP95Px);
            if (machine.empty()) machine = machineLine();
            ++done;
            std::fprintf(stderr, "%s[%zu/%zu] %-9s %s=%-8s false shadow %6s %%  false lit %6s %%%s",
                         tty ? "\r" : "", done, total, stage.c_str(), axis.name.c_str(),
                         num(v).c_str(), num(acc.falseShadowPct, 3).c_str(),
                         num(acc.falseLitPct, 3).c_str(), tty ? "\033[K" : "\n");
        }
        // Where the error is undefined (no lit or no shadowed pixel could be measured, e.g. a
        // light so low that no shadow shows) the method is neither working nor broken: only
        // the measured values are judged.
        std::vector<double> judgedXs, judgedErrors;
        for (std::size_t k = 0; k < line.xs.size(); ++k)
            if (!std::isnan(line.ys[k])) {
                judgedXs.push_back(line.xs[k]);
                judgedErrors.push_back(line.ys[k]);
            }
        WorkingRange r = workingRange(judgedXs, judgedErrors, a.threshold);
        breaks.add({axis.name, stage, treeName(c.tree), num(a.threshold), num(r.best, 8),
                    num(r.bestError), r.works ? "yes" : "no", num(r.from, 8), num(r.to, 8),
                    num(r.breaksBefore, 8), num(r.breaksAfter, 8)});
        chart.push_back(line);
        edges.push_back(edge);
    }
    if (tty) std::fprintf(stderr, "\n");

    std::string base = a.out + "/sweep-" + axis.name;
    for (const auto& [path, text] :
         {std::pair<std::string, std::string>{base + ".csv", points.csv()},
          {base + "-breaks.csv", breaks.csv()},
          {base + ".dat", gnuplotBlocks(chart)},
          {base + "-edge.dat", gnuplotBlocks(edges)}}) {
        std::string err = writeTextFile(path, text);
        if (!err.empty()) throw UsageError("--out: " + err);
    }
    std::string name = "sweep-" + axis.name;
    std::ostringstream g;
    // Two panels: the balanced error (acne and missing shadows), and the 95th-percentile edge
    // error, where shadows that slide off their casters (too much margin) show first.
    g << "# Regenerate: gnuplot " << name << ".gp\n"
      << "set terminal pngcairo size 960,900 font 'sans,10'\nset output '" << name << ".png.tmp'\n"
      << "set key outside right top\nset grid\nset multiplot layout 2,1\n"
      << "set title \"Error along " << axis.name << " (" << sized.width << "x" << sized.height
      << "), threshold " << a.threshold << " %\\n"
      << machine << "\"\n"
      << "set xlabel '" << axis.unit << "'\n"
      << (axis.logX ? "set logscale x\n" : "")
      << (axis.name == "elevation" ? "set xrange [*:*] reverse\n" : "")
      << "set logscale y\nset yrange [0.01:100]\nshown(y) = y < 0.01 ? 0.01 : y\n"
      << "set ylabel 'balanced error %, (false shadow + false lit) / 2 (0 drawn at 0.01)'\n"
      << "plot for [i=0:*] '" << name << ".dat' index i using 1:(shown($2)) with linespoints pt 7 "
      << "title columnheader(1), \\\n"
      << "     " << a.threshold << " with lines dt 2 lc rgb 'black' title 'threshold'\n"
      << "unset logscale y\nset yrange [0:*]\nset title 'Shadow edge error, 95th percentile'\n"
      << "set ylabel 'edge error p95, pixels'\n"
      << "plot for [i=0:*] '" << name << "-edge.dat' index i using 1:2 with linespoints pt 7 "
      << "title columnheader(1)\n"
      << "unset multiplot\nset output\nsystem('mv " << name << ".png.tmp " << name << ".png')\n";
    std::string problem = runGnuplot(a.out, base + ".gp", g.str());

    // The verdict per stage, readable.
    for (const auto& row : breaks.rows) {
        std::cout << "  " << row[1] << " (" << row[2] << "): ";
        if (row[6] == "no")
            std::cout << "never under " << row[3] << " % (best " << row[5] << " % at " << row[4]
                      << ")\n";
        else
            std::cout << "works from " << row[7] << " to " << row[8] << " (best " << row[5]
                      << " % at " << row[4] << "); breaks at " << (row[9] == "na" ? "-" : row[9])
                      << " / " << (row[10] == "na" ? "-" : row[10]) << "\n";
    }
    if (!problem.empty()) std::cerr << "shadowlab: " << problem << "\n";
    std::cout << "wrote " << base << ".csv, " << base << "-breaks.csv"
              << (problem.empty() ? ", " + base + ".png" : "") << "\n";
    return kOk;
}

}  // namespace

Command addSweepCommand(CLI::App& app) {
    auto args = std::make_shared<SweepArgs>();
    auto* cmd = app.add_subcommand(
        "sweep", "every shadow stage along one axis: error per point and where it breaks");
    cmd->add_option("axis", args->axis, "elevation | margin | offset | near-far | map-size")
        ->required();
    cmd->add_option("--out", args->out, "output folder (default out/sweep)");
    cmd->add_option("--glsl", args->glsl, "shader tree: core or legacy (fixed always runs legacy)");
    cmd->add_option("--size", args->size, "image size WxH (default 640x480)");
    cmd->add_option("--threshold", args->threshold,
                    "balanced error % above which a method counts as broken (default 5)");
    cmd->add_flag("--quick", args->quick, "four or five points per axis");
    cmd->add_option("--backend", args->backend, "headless backend: auto|osmesa|egl");
    return {cmd, [args] { return guarded([&] { return runSweep(*args); }); }};
}

}  // namespace sl
