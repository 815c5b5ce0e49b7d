// `shadowlab bench [--out DIR] [--quick]`: every stage's frame time per pass, beside `phong` in
// the same run, with the accuracy figures of the same configuration; CSV, JSON and charts.
#include <unistd.h>

#include <iostream>
#include <map>

#include "app/bench_output.h"
#include "app/bench_report.h"
#include "app/commands.h"

namespace sl {

namespace {

struct BenchArgs {
    std::string out = "out/bench";
    std::string glsl = "core";
    std::string backend = "auto";
    bool quick = false;
    std::string only;            // keep configurations whose series contains this
    int frames = 0, warmup = 0;  // 0 = the default for the mode
    int blocks = 0;              // interleaved blocks per configuration; 0 = the mode's default
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
    // How cost grows with the map: each shadow method at its defaults, the map size varied.
    struct Variant {
        std::string series, stage;
        std::vector<std::pair<std::string, std::string>> sets;
    };
    std::vector<Variant> variants = {
        {"rgb", "rgb", {}},
        {"depth", "depth", {}},
        {"bias", "bias", {}},
        {"margin/constant", "margin", {}},
        {"margin/slope", "margin", {{"margin-kind", "slope"}}},
        {"hardware/linear", "hardware", {}},
        {"hardware/nearest", "hardware", {{"filter", "nearest"}}},
        {"fixed", "fixed", {}},
        {"hardware/pcf3x3", "hardware", {{"filter", "pcf3x3"}}},
        // The tutorials' methods (stage peers), on the same axes as ours.
        {"peers/learnopengl", "peers", {{"method", "learnopengl"}}},
        {"peers/opengl-tutorial", "peers", {{"method", "opengl-tutorial"}}},
        {"peers/normal-offset", "peers", {{"method", "normal-offset"}}},
    };
    for (const Variant& v : variants)
        for (int size : mapSizes) {
            auto sets = v.sets;
            sets.emplace_back("map-size", std::to_string(size));
            add("map-size", v.series, v.stage, sets, 640, 480,
                v.stage == "fixed" ? std::optional<GlslTree>(GlslTree::Legacy) : std::nullopt);
        }
    // Storage formats at a 1024 map.
    const std::string m = "1024";
    if (!quick) {
        add("format", "rgb/packed", "rgb", {{"encoding", "packed"}, {"map-size", m}});
        for (const char* f : {"16", "24", "32f"})
            add("format", std::string("depth/") + f, "depth",
                {{"depth-format", f}, {"map-size", m}});
        for (const char* s : {"rgb8", "depth16", "depth24", "depth32f"})
            add("format", std::string("margin/") + s, "margin", {{"storage", s}, {"map-size", m}});
        for (const char* f : {"16", "32f"})
            add("format", std::string("hardware/") + f, "hardware",
                {{"depth-format", f}, {"map-size", m}});
        add("format", "hardware/cull-front", "hardware",
            {{"shadow-cull", "front"}, {"map-size", m}});
    }
    // The mirror: both methods, and the texture method at fixed sizes against its footprint.
    add("mirror", "mirror/texture", "mirror", {});
    add("mirror", "mirror/stencil", "mirror", {{"mirror-method", "stencil"}});
    for (const char* s : quick ? std::vector<const char*>{"256"}
                               : std::vector<const char*>{"128", "256", "512", "1024"})
        add("mirror", std::string("mirror/texture-") + s, "mirror", {{"mirror-size", s}});
    // How cost grows with the window: every stage at its defaults.
    for (const auto& [w, h] : windows)
        for (const auto& s : stageRegistry())
            if (s.id != "phong")  // phong is every context's baseline already
                add("window", s.id, s.id, {}, w, h,
                    s.legacyOnly ? std::optional<GlslTree>(GlslTree::Legacy) : std::nullopt);
    return out;
}

int runBench(const BenchArgs& a) {
    GlslTree tree = a.glsl == "core" ? GlslTree::Core
                    : a.glsl == "legacy"
                        ? GlslTree::Legacy
                        : throw UsageError("--glsl: '" + a.glsl + "' is not one of core, legacy");
    Backend backend = toBackend(a.backend);
    int frames = a.frames > 0 ? a.frames : a.quick ? 3 : 60;
    int warmup = a.warmup > 0 ? a.warmup : a.quick ? 1 : 3;
    int blocks = std::min(frames, a.blocks > 0 ? a.blocks : a.quick ? 3 : 15);
    int framesPerBlock = std::max(1, frames / blocks);
    makeOutputDir(a.out);

    // Phong at every (tree, scene, size) a configuration uses, measured right before it.
    std::vector<BenchConfig> configs;
    std::map<std::string, bool> baselined;
    for (BenchConfig& c : plan(a.quick, tree)) {
        if (c.series.find(a.only) == std::string::npos) continue;
        std::string key = contextKey(c, c.sceneName());
        if (!baselined[key]) {
            BenchConfig base = c;
            base.group = "baseline";
            base.series = "phong";
            base.stage = "phong";
            base.sets.clear();
            base.scene = c.sceneName();  // the same scene as the stage it is the baseline of
            configs.push_back(base);
            baselined[key] = true;
        }
        configs.push_back(c);
    }

    BenchRig rig(backend);
    std::vector<Measured> results;
    std::string machine;
    bool tty = isatty(STDERR_FILENO);
    for (std::size_t k = 0; k < configs.size(); ++k) {
        const BenchConfig& c = configs[k];
        Measured m{c, c.sceneName(), {}, {}, {}, {}, {}, {}, {}};
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
            auto moving = rig.timeBesidePhong(c, framesPerBlock, blocks, true);
            m.still = still.config;
            m.phongStill = still.phong;
            m.ratioStill = still.ratio;
            m.moving = moving.config;
            m.phongMoving = moving.phong;
            m.ratioMoving = moving.ratio;
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
                    "timed frames per configuration and light, each side (default 60; quick 3)")
        ->check(CLI::Range(1, 10000));
    cmd->add_option("--blocks", args->blocks,
                    "interleaved blocks (ABBA against phong) the frames are split into; the "
                    "ratio is the median of the per-block ratios (default 15; quick 3)")
        ->check(CLI::Range(1, 1000));
    cmd->add_option("--warmup", args->warmup, "untimed frames first (default 3; quick 1)")
        ->check(CLI::Range(1, 1000));
    cmd->add_option("--only", args->only,
                    "measure only series containing this text, e.g. hardware");
    cmd->add_option("--glsl", args->glsl, "shader tree: core or legacy (fixed always runs legacy)");
    cmd->add_option("--backend", args->backend, "headless backend: auto|osmesa|egl");
    return {cmd, [args] { return guarded([&] { return runBench(*args); }); }};
}

}  // namespace sl
