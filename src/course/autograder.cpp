#include "course/autograder.h"

#include <archive.h>
#include <archive_entry.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <sstream>

#include "io/data_paths.h"
#include "io/files.h"
#include "io/usage_error.h"

namespace sl {

namespace fs = std::filesystem;

std::string autograderSetupScript() {
    return R"SH(#!/usr/bin/env bash
# Gradescope runs this once, as root, to build the image (Ubuntu 22.04 base): the packages
# (scripts/deps.sh), then the program from the sources beside it (the files its build reads).
set -euo pipefail
cd "$(dirname "$0")/shadowlab"
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
# Gradescope's submission_metadata.json says when the hand-in came (the late policy's time).
metadata=()
[ -f "$root/submission_metadata.json" ] && metadata=(--submission-metadata "$root/submission_metadata.json")
"$program" check --assignment "$root/source/assignment.json" --shaders "$root/submission" \
    --report "$results" --format gradescope --time-limit 60 "${metadata[@]}"
status=$?
if [ "$status" -eq 3 ]; then
    # NOT GRADED rows: the machine's failure, no score yet (results.json has none). The run
    # fails, so Gradescope shows no grade rather than a partial one; rerun the autograder.
    echo "run_autograder: not graded (the grading machine failed, not the submission): rerun" >&2
    exit 3
fi
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

// The source kit's list: source_kit.txt, written by the build (cmake/source_kit.py) and
// installed with the instructor's `solutions` component. An installed copy has it in
// share/shadowlab/solutions (which mirrors the source tree; the student edition has none); the
// build tree beside the program, its files in the sources.
SourceKit findSourceKit() {
    std::string kitRoot = dataDir() + "/solutions";
    std::string installed = kitRoot + "/source_kit.txt";
    if (fs::is_regular_file(installed)) return {installed, kitRoot};
    char exe[4096] = {0};
    ssize_t length = ::readlink("/proc/self/exe", exe, sizeof exe - 1);
    std::string beside =
        length > 0 ? fs::path(std::string(exe, length)).parent_path().string() + "/source_kit.txt"
                   : std::string();
    if (!beside.empty() && fs::is_regular_file(beside)) return {beside, SHADOWLAB_SOURCE_DIR};
    throw UsageError(
        "release --gradescope: no source_kit.txt (the files building shadowlab "
        "reads) in " +
        printableName(kitRoot) +
        " nor beside the program: build it (`cmake --build build`), or install the "
        "instructor's component (`cmake --install build --component solutions`)");
}

std::vector<std::string> readSourceKit(const SourceKit& kit) {
    std::string text;
    std::string err = readRegularFile(kit.list, 1u << 20, text);
    if (!err.empty()) throw UsageError("release --gradescope: " + err);
    std::vector<std::string> files;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.empty()) continue;
        fs::path p(line);
        bool inside = p.is_relative() && std::none_of(p.begin(), p.end(), [](const fs::path& part) {
                          return part == "..";
                      });
        if (!inside)
            throw UsageError("release --gradescope: " + printableName(kit.list) + ": '" +
                             printableName(line) + "' is not a path inside the sources");
        files.push_back(line);
    }
    if (files.empty())
        throw UsageError("release --gradescope: " + printableName(kit.list) + " lists no file");
    return files;
}

std::string writeAutograderZip(const Assignment& a, const std::string& assignmentPath,
                               const std::string& outDir) {
    (void)a;
    SourceKit kit = findSourceKit();
    std::vector<std::string> files = readSourceKit(kit);
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
    for (const std::string& f : files) {
        std::string path = kit.root + "/" + f;
        std::string text;
        err = readRegularFile(path, 16u << 20, text);
        if (!err.empty())
            throw UsageError("release --gradescope: " + err + " (listed in " +
                             printableName(kit.list) + "; build or install again)");
        bool executable =
            (fs::status(path).permissions() & fs::perms::owner_exec) != fs::perms::none;
        w.add("shadowlab/" + f, text, executable ? 0755 : 0644);
    }
    if (archive_write_close(w.a.get()) != ARCHIVE_OK)
        throw UsageError("release: cannot finish " + printableName(zip));
    return "autograder.zip";
}

}  // namespace sl
