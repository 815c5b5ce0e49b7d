#include "course/autograder.h"

#include <archive.h>
#include <archive_entry.h>

#include <filesystem>
#include <memory>

#include "io/files.h"
#include "scene/scene_json.h"

namespace sl {

namespace fs = std::filesystem;

std::string autograderSetupScript() {
    return R"SH(#!/usr/bin/env bash
# Gradescope runs this once to build the image (Ubuntu 22.04 base): the packages, then shadowlab.
set -euo pipefail
cd /autograder/source/shadowlab
bash scripts/deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF
cmake --build build -j"$(nproc)" --target shadowlab
)SH";
}

std::string autograderRunScript() {
    return R"SH(#!/usr/bin/env bash
# Gradescope runs this per submission: grade /autograder/submission by the assignment and write
# /autograder/results/results.json. AUTOGRADER_ROOT moves the tree (tests); SHADOWLAB names the
# program when it is not the one setup.sh built.
set -uo pipefail
root="${AUTOGRADER_ROOT:-/autograder}"
program="${SHADOWLAB:-$root/source/shadowlab/build/shadowlab}"
mkdir -p "$root/results"
results="$root/results/results.json"
rm -f "$results"
# Gradescope's default container: 768 MB and under one CPU. One worker at a time, each bounded;
# the worker's memory limit is left to follow the container's cgroup (512 MB of 768: a memory
# bomb is reported, not the container killed), the CPU count to its quota.
"$program" check --assignment "$root/source/assignment.json" --shaders "$root/submission" \
    --report "$results" --format gradescope --time-limit 60
status=$?
if [ ! -s "$results" ]; then
    # Never leave Gradescope without a results file: say what happened, 0 points.
    printf '{"score": 0, "output": "The grader could not grade this submission (exit %s). Your instructor has the log.", "visibility": "visible", "tests": []}\n' "$status" > "$results"
fi
exit 0
)SH";
}

namespace {

struct Writer {
    std::unique_ptr<archive, int (*)(archive*)> a{archive_write_new(), archive_write_free};

    void add(const std::string& name, const std::string& data, int mode) {
        std::unique_ptr<archive_entry, void (*)(archive_entry*)> e(archive_entry_new(),
                                                                   archive_entry_free);
        archive_entry_set_pathname(e.get(), name.c_str());
        archive_entry_set_filetype(e.get(), AE_IFREG);
        archive_entry_set_perm(e.get(), mode);
        archive_entry_set_size(e.get(), la_int64_t(data.size()));
        if (archive_write_header(a.get(), e.get()) != ARCHIVE_OK ||
            archive_write_data(a.get(), data.data(), data.size()) != la_ssize_t(data.size()))
            throw std::runtime_error(std::string("autograder.zip: ") +
                                     archive_error_string(a.get()));
    }
};

}  // namespace

std::string writeAutograderZip(const Assignment& a, const std::string& assignmentPath,
                               const std::string& outDir) {
    (void)a;
    std::string source = dataDir();
    if (!fs::exists(source + "/CMakeLists.txt") || !fs::exists(source + "/src"))
        throw UsageError(
            "release --gradescope: needs shadowlab's source tree (CMakeLists.txt, src/) in " +
            printableName(source) + "; run it from a checkout");
    std::string assignmentText;
    std::string err = readRegularFile(assignmentPath, 1u << 20, assignmentText);
    if (!err.empty()) throw UsageError("--assignment: " + err);
    std::string zip = outDir + "/autograder.zip";
    Writer w;
    archive_write_set_format_zip(w.a.get());
    if (archive_write_open_filename(w.a.get(), zip.c_str()) != ARCHIVE_OK)
        throw UsageError("release: cannot write " + printableName(zip));
    w.add("setup.sh", autograderSetupScript(), 0755);
    w.add("run_autograder", autograderRunScript(), 0755);
    w.add("assignment.json", assignmentText, 0644);
    for (const char* top : {"CMakeLists.txt", "CMakePresets.json", "src", "shaders_core",
                            "shaders_legacy", "scenes", "scripts", "slides_examples"}) {
        fs::path p = fs::path(source) / top;
        std::vector<fs::path> files;
        if (fs::is_regular_file(p)) {
            files.push_back(p);
        } else if (fs::is_directory(p)) {
            for (const auto& e : fs::recursive_directory_iterator(p))
                if (e.is_regular_file() && !e.is_symlink()) files.push_back(e.path());
        }
        std::sort(files.begin(), files.end());
        for (const fs::path& f : files) {
            std::string text;
            err = readRegularFile(f.string(), 16u << 20, text);
            if (!err.empty()) throw UsageError("release --gradescope: " + f.string() + ": " + err);
            bool executable =
                (fs::status(f).permissions() & fs::perms::owner_exec) != fs::perms::none;
            w.add("shadowlab/" + fs::relative(f, source).string(), text, executable ? 0755 : 0644);
        }
    }
    if (archive_write_close(w.a.get()) != ARCHIVE_OK)
        throw UsageError("release: cannot finish " + printableName(zip));
    return "autograder.zip";
}

}  // namespace sl
