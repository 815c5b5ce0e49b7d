// `shadowlab bench [--out DIR] [--quick]`: every stage's frame time per pass, beside `phong` in
// the same run, with the accuracy figures of the same configuration; CSV, JSON and charts.
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "app/commands.h"
#include "bench/bench_equal.h"
#include "bench/bench_output.h"
#include "bench/bench_report.h"
#include "io/files.h"
#include "io/usage_error.h"
#include "metrics/callgrind.h"
#include "stages/registry.h"

namespace sl {

namespace {

struct BenchArgs {
    std::string out = "out/bench";
    std::string glsl = "core";
    std::string backend = "auto";
    bool quick = false;
    std::string only;               // keep configurations whose series contains this
    int frames = 0, warmup = 0;     // 0 = the default for the mode
    int blocks = 0;                 // interleaved blocks per configuration; 0 = the mode's default
    bool instructions = false;      // also count instructions per frame under callgrind
    std::string instructionsChild;  // set: this process runs under callgrind, counting this plan
    bool equalAccuracy = false;     // the equal-accuracy search (always in a full run)
};

// The configurations measured, in order. Baselines (phong) come first for each context.
std::vector<BenchConfig> plan(bool quick, GlslTree tree) {
    std::vector<int> mapSizes =
        quick ? std::vector<int>{256, 1024} : std::vector<int>{128, 256, 512, 1024, 2048, 4096};
    std::vector<std::pair<int, int>> windows =
        quick ? std::vector<std::pair<int, int>>{{320, 240}, {640, 480}}
              : std::vector<std::pair<int, int>>{{320, 240}, {640, 480}, {1280, 960}};
    std::vector<BenchConfig> out;
    auto add = [&](std::string group, std::string series, std::string stage,
                   std::vector<std::pair<std::string, std::string>> sets, int w = 640, int h = 480,
                   std::optional<GlslTree> forced = std::nullopt) {
        BenchConfig c;
        c.group = std::move(group);
        c.series = std::move(series);
        c.stage = std::move(stage);
        c.tree = forced ? *forced : tree;
        c.sets = std::move(sets);
        c.width = w;
        c.height = h;
        out.push_back(std::move(c));
    };
    // The stages' own series (StageDefinition::benchSeries), group by group: the settings a
    // series declares, then the axis varied here; at 640x480.
    auto addSeries = [&](BenchGroup group,
                         std::vector<std::vector<std::pair<std::string, std::string>>> axis) {
        for (const StageSeries& s : benchSeriesIn(group)) {
            if (quick && !s.series->inQuick) continue;
            for (const auto& point : axis) {
                auto sets = s.series->sets;
                sets.insert(sets.end(), point.begin(), point.end());
                add(benchGroupName(group), s.series->name, s.stage->id, sets, 640, 480,
                    s.stage->legacyOnly ? std::optional<GlslTree>(GlslTree::Legacy) : std::nullopt);
            }
        }
    };
    // How cost grows with the map: each shadow method, the map size varied.
    std::vector<std::vector<std::pair<std::string, std::string>>> sizes;
    for (int size : mapSizes) sizes.push_back({{"map-size", std::to_string(size)}});
    addSeries(BenchGroup::MapSize, sizes);
    // Storage formats at a 1024 map.
    if (!quick) addSeries(BenchGroup::Format, {{{"map-size", "1024"}}});
    // The mirror: its methods, and the texture method at fixed sizes against its footprint.
    addSeries(BenchGroup::Mirror, {{}});
    // How cost grows with the window: every stage at its defaults.
    for (const auto& [w, h] : windows)
        for (const auto& s : stageRegistry())
            if (s.id != lightingStage().id)  // every context's baseline already
                add("window", s.id, s.id, {}, w, h,
                    s.legacyOnly ? std::optional<GlslTree>(GlslTree::Legacy) : std::nullopt);
    return out;
}

// What a run measures: the plan, filtered by --only, with phong before the first configuration
// of every context (tree, scene, size).
std::vector<BenchConfig> benchConfigs(const BenchArgs& a, GlslTree tree) {
    std::vector<BenchConfig> configs;
    std::map<std::string, bool> baselined;
    for (BenchConfig& c : plan(a.quick, tree)) {
        if (c.series.find(a.only) == std::string::npos) continue;
        std::string key = contextKey(c, c.sceneName());
        if (!baselined[key]) {
            BenchConfig base = c;
            base.group = "baseline";
            base.series = lightingStage().id;
            base.stage = lightingStage().id;
            base.sets.clear();
            base.scene = c.sceneName();  // the same scene as the stage it is the baseline of
            configs.push_back(base);
            baselined[key] = true;
        }
        configs.push_back(c);
    }
    return configs;
}

// Which configurations `--instructions` counts: the 640x480 ones the charts and targets use.
bool countsInstructions(const BenchConfig& c) {
    return c.width == 640 && c.height == 480 &&
           (c.group == "baseline" || c.group == "map-size" || c.group == "window" ||
            c.group.rfind("equal-accuracy", 0) == 0);
}

constexpr int kCountedFrames = 2;  // callgrind's counts repeat: two frames are plenty

// The plan the child counts, one configuration a line: stage, tree, scene, width, height and
// the settings, tab-separated (the settings as NAME=VALUE separated by spaces).
std::string planLine(const BenchConfig& c) {
    std::string sets;
    for (const auto& [name, value] : c.sets) sets += (sets.empty() ? "" : " ") + name + "=" + value;
    return c.stage + "\t" + treeName(c.tree) + "\t" + c.sceneName() + "\t" +
           std::to_string(c.width) + "\t" + std::to_string(c.height) + "\t" + sets + "\n";
}

BenchConfig parsePlanLine(const std::string& line) {
    std::vector<std::string> field;
    std::istringstream in(line);
    for (std::string f; std::getline(in, f, '\t');) field.push_back(f);
    if (field.size() < 5) throw UsageError("--instructions-child: bad plan line '" + line + "'");
    BenchConfig c;
    c.stage = field[0];
    c.tree = field[1] == "legacy" ? GlslTree::Legacy : GlslTree::Core;
    c.scene = field[2];
    c.width = std::stoi(field[3]);
    c.height = std::stoi(field[4]);
    std::istringstream sets(field.size() > 5 ? field[5] : "");
    for (std::string nv; sets >> nv;) {
        std::size_t eq = nv.find('=');
        if (eq != std::string::npos) c.sets.emplace_back(nv.substr(0, eq), nv.substr(eq + 1));
    }
    return c;
}

// The child under callgrind: every configuration of the plan file, still then moving, each
// through countedFrames() (one dump each, in this order).
int runInstructionsChild(const BenchArgs& a) {
    std::ifstream plan(a.instructionsChild);
    if (!plan) throw UsageError("--instructions-child: cannot read '" + a.instructionsChild + "'");
    BenchRig rig(toBackend(a.backend));
    for (std::string line; std::getline(plan, line);) {
        if (line.empty()) continue;
        BenchConfig c = parsePlanLine(line);
        for (bool moving : {false, true}) {
            rig.prepare(c);
            // Uncounted: the stage switch re-creates the map, and llvmpipe may compile state
            // variants on a second frame (fixed at 128 counted 156 M against 28.8 M after one).
            // Two, so that the first counted frame's light differs from the last uncounted one.
            rig.time(2, 0, moving);
            unsigned renders = countedFrames(rig, kCountedFrames, moving);
            // Every counted moving frame must re-render the map (a stage that has one).
            if (moving && rig.renderer().stats.mapSize > 0 && renders != unsigned(kCountedFrames))
                throw std::runtime_error("--instructions-child: " + c.series + " counted " +
                                         std::to_string(renders) + " map renders in " +
                                         std::to_string(kCountedFrames) +
                                         " frames with the light moving");
        }
    }
    return kOk;
}

// Runs this program again under callgrind and fills each counted result's instructions.
// Before any timing: what --instructions needs (valgrind, and this build marking the frames).
void checkInstructionsPossible() {
    if (std::system("command -v valgrind >/dev/null 2>&1") != 0)
        throw UsageError("--instructions needs valgrind (apt-get install valgrind)");
    if (!callgrindMarkersBuiltIn())
        throw UsageError(
            "--instructions: this build has no valgrind/callgrind.h (it marks the counted "
            "frames): rebuild now that valgrind is installed (bash scripts/build.sh configures "
            "again)");
}

void countInstructions(const BenchArgs& a, std::vector<Measured>& results) {
    std::string dir = a.out + "/callgrind";
    makeOutputDir(dir);
    std::string out = dir + "/frames.out";
    std::system(("rm -f " + shellQuote(out) + "*").c_str());
    std::string planFile = dir + "/plan.tsv";
    std::string plan;
    for (const Measured& m : results)
        if (countsInstructions(m.config)) plan += planLine(m.config);
    std::string err = writeTextFile(planFile, plan);
    if (!err.empty()) throw UsageError("--out: " + err);
    std::string args = "bench --instructions-child " + shellQuote(planFile) + " --backend " +
                       shellQuote(a.backend);
    char exe[4096] = {0};
    ssize_t length = readlink("/proc/self/exe", exe, sizeof exe - 1);
    std::string self = length > 0 ? std::string(exe, length) : "/proc/self/exe";
    std::string command =
        callgrindCommand(self, out, args) + " >" + shellQuote(dir + "/valgrind.log") + " 2>&1";
    std::fprintf(stderr, "counting instructions under callgrind (log: %s/valgrind.log)...\n",
                 dir.c_str());
    if (std::system(command.c_str()) != 0)
        throw std::runtime_error("--instructions: the run under callgrind failed; see " + dir +
                                 "/valgrind.log");
    int dump = 0;
    auto next = [&]() {
        std::ifstream f(out + "." + std::to_string(++dump));
        std::stringstream text;
        text << f.rdbuf();
        return instructionsPerFrame(parseCallgrindTotal(text.str()), kCountedFrames);
    };
    std::map<std::string, const Measured*> phong;
    for (Measured& m : results) {
        if (!countsInstructions(m.config)) continue;
        m.instructions.still = next();
        m.instructions.moving = next();
        if (m.config.group == "baseline") phong[contextKey(m.config, m.scene)] = &m;
    }
    for (Measured& m : results) {
        auto base = phong.find(contextKey(m.config, m.scene));
        if (base == phong.end()) continue;
        m.instructions.ratioStill = m.instructions.still / base->second->instructions.still;
        m.instructions.ratioMoving = m.instructions.moving / base->second->instructions.moving;
    }
}

int runBench(const BenchArgs& a) {
    GlslTree tree = a.glsl == "core" ? GlslTree::Core
                    : a.glsl == "legacy"
                        ? GlslTree::Legacy
                        : throw UsageError("--glsl: '" + a.glsl + "' is not one of core, legacy");
    Backend backend = toBackend(a.backend);
    if (!a.instructionsChild.empty()) return runInstructionsChild(a);
    if (a.instructions) checkInstructionsPossible();
    int frames = a.frames > 0 ? a.frames : a.quick ? 3 : 40;
    int warmup = a.warmup > 0 ? a.warmup : a.quick ? 1 : 3;
    int blocks = std::min(frames, a.blocks > 0 ? a.blocks : a.quick ? 3 : 10);
    int framesPerBlock = std::max(1, frames / blocks);
    makeOutputDir(a.out);
    std::vector<BenchConfig> configs = benchConfigs(a, tree);

    BenchRig rig(backend);
    std::vector<Measured> results;
    std::string machine;
    bool tty = isatty(STDERR_FILENO);
    for (std::size_t k = 0; k < configs.size(); ++k) {
        const BenchConfig& c = configs[k];
        Measured m{c, c.sceneName(), {}, {}, {}, {}, {}, {}, {}, {}};
        if (c.group == "baseline") {
            // phong on its own: its ratio is 1 by definition. It draws no map, so a moving light
            // costs it nothing: one measurement (still and moving blocks pooled) serves both rows,
            // which therefore cannot disagree.
            rig.prepare(c);
            PassSamples pooled;
            for (int k = 0; k < blocks; ++k)
                pooled.append(rig.time(k == 0 ? warmup : 1, framesPerBlock, k % 2 == 1));
            m.still = m.phongStill = m.moving = m.phongMoving = pooled.summary();
            m.ratioStill = m.ratioMoving = RatioSummary{blocks, 1.0, 1.0, 1.0};
        } else {
            auto still = rig.timeBesidePhong(c, framesPerBlock, blocks, false);
            m.setTimes(still, rig.timeBesidePhong(c, framesPerBlock, blocks, true));
        }
        if (machine.empty()) machine = machineLine();
        rig.prepare(c);
        m.accuracy = rig.accuracy();
        results.push_back(m);
        std::fprintf(stderr,
                     "%s[%zu/%zu] %-8s %-22s %-7s %4dx%-4d %-28s still %7.2f ms %5.2fx  moving "
                     "%7.2f ms %5.2fx  "
                     "error %6s %%%s",
                     tty ? "\r" : "", k + 1, configs.size(), c.group.c_str(), c.series.c_str(),
                     treeName(c.tree), c.width, c.height, c.setsText().c_str(),
                     m.still.frame.median, m.ratio(false), m.moving.frame.median, m.ratio(true),
                     num(m.accuracy.errorPct, 3).c_str(), tty ? "\033[K" : "\n");
    }
    if (tty) std::fprintf(stderr, "\n");
    if (a.equalAccuracy || !a.quick) {
        auto log = [&](const std::string& line) {
            std::fprintf(stderr, "equal accuracy: %s\n", line.c_str());
        };
        for (Measured& m : searchEqualAccuracy(rig, equalAccuracyCandidates(a.quick, tree, a.only),
                                               framesPerBlock, blocks, AccuracyBar{}, log))
            results.push_back(m);
    }
    if (a.instructions) countInstructions(a, results);
    BenchReport report = writeBenchReport(a.out, machine, results);
    std::cout << report.summary;
    if (!report.chartProblem.empty()) std::cerr << "shadowlab: " << report.chartProblem << "\n";
    std::cout << "wrote " << a.out << "/bench.csv, bench.json"
              << (report.chartProblem.empty() ? " and charts" : "") << "\n";
    return kOk;
}

}  // namespace

Command addBenchCommand(CLI::App& app) {
    auto args = std::make_shared<BenchArgs>();
    auto* cmd = app.add_subcommand(
        "bench", "time every stage per pass beside phong, with its accuracy; CSV, JSON, charts");
    cmd->add_option("--out", args->out, "output folder (default out/bench)");
    cmd->add_flag("--quick", args->quick, "a few frames, two map sizes, every stage (under 30 s)");
    cmd->add_option("--frames", args->frames,
                    "timed frames per configuration and light, each side (default 40; quick 3)")
        ->check(CLI::Range(1, 10000));
    cmd->add_option("--blocks", args->blocks,
                    "interleaved blocks (ABBA against phong) the frames are split into; the "
                    "ratio is the median of the per-block ratios (default 10; quick 3)")
        ->check(CLI::Range(1, 1000));
    cmd->add_flag("--instructions", args->instructions,
                  "also count instructions per frame (640x480 configurations) under valgrind's "
                  "callgrind: slow, but repeatable on a loaded machine");
    cmd->add_option("--instructions-child", args->instructionsChild,
                    "internal: the run under callgrind that --instructions starts (its plan file)")
        ->group("");
    cmd->add_flag("--equal-accuracy", args->equalAccuracy,
                  "search each method's cheapest configuration reaching edge p95 <= 2 px and "
                  "error <= 0.1 % (always in a full run; with --quick on request)");
    cmd->add_option("--warmup", args->warmup, "untimed frames first (default 3; quick 1)")
        ->check(CLI::Range(1, 1000));
    cmd->add_option("--only", args->only,
                    "measure only series containing this text, e.g. hardware");
    cmd->add_option("--glsl", args->glsl, "shader tree: core or legacy (fixed always runs legacy)");
    cmd->add_option("--backend", args->backend, "headless backend: auto|osmesa|egl");
    return {cmd, [args] { return guarded([&] { return runBench(*args); }); }};
}

}  // namespace sl
