#include "course/release.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <functional>
#include <sstream>

#include "io/data_paths.h"
#include "io/files.h"
#include "io/usage_error.h"
#include "stages/request.h"

namespace sl {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kMaxShaderBytes = 1u << 20;

void writeText(const std::string& path, const std::string& text) {
    std::error_code ec;
    std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
    std::string err = writeFileAtomically(path, text.data(), text.size());
    if (!err.empty()) throw UsageError("release: " + err);
}

// How a student gets the program: the student edition (every solution region stubbed), the
// .deb or the default install of a build (README.md, "Systems"; docs/assignment.md).
std::string installSection() {
    return "\n## Install shadowlab\n\n"
           "Install the student edition, the program `check` and `window` below need: the Debian\n"
           "package your instructor gives you (`sudo apt-get install ./shadowlab_*.deb`), or\n"
           "from its source (`bash scripts/deps.sh` installs what the build needs):\n\n"
           "```sh\ncmake --preset default && cmake --build build -j\"$(nproc)\" --target "
           "shadowlab\n"
           "cmake --install build --prefix ~/shadowlab && export "
           "PATH=~/shadowlab/bin:$PATH\n```\n\n"
           "It grades your work as the instructor's copy does (the same references and bounds).\n";
}

std::string numberText(double v) {
    std::ostringstream o;
    o << v;
    return o.str();
}

// The late policy in a student's words (docs/assignment.md, "Late policy"), or nothing.
std::string lateSection(const Assignment& a) {
    if (!a.late) return "";
    const LatePolicy& p = *a.late;
    std::ostringstream r;
    r << "\n## Late policy\n\nDeadline: " << p.deadlineText;
    if (p.graceMinutes > 0) r << ", with " << numberText(p.graceMinutes) << " minutes of grace";
    r << ". After it, each day or part of a day costs " << numberText(p.penaltyPerDayPct)
      << " % of the assignment's points";
    if (p.capPct < 100) r << ", at most " << numberText(p.capPct) << " % in all";
    r << " (never more than you earned).\n";
    return r.str();
}

std::string studentReadme(const Assignment& a) {
    std::ostringstream r;
    r << "# " << a.name << "\n\n";
    if (!a.dueDate.empty()) r << "Due: " << a.dueDate << "\n\n";
    r << "## What to write\n\n"
      << "Each file below has a part marked `TODO`: it compiles and runs as it is, but draws no\n"
      << "shadows (the \"not done yet\" picture). Replace the TODO with your code; change nothing\n"
      << "else the stage relies on (the uniforms and inputs it declares).\n\n"
      << "| stage | points | file(s) | what to write |\n|---|---|---|---|\n";
    for (const AssignmentStage* s : a.due()) {
        std::string files;
        for (const auto& f : s->files)
            files += (files.empty() ? "" : ", ") + ("`shaders/" + f + "`");
        r << "| " << s->stage << " (" << s->tree << ") | " << s->points << " | " << files << " | "
          << (s->todo.empty() ? "see the TODO in the file" : s->todo) << " |\n";
    }
    r << lateSection(a) << installSection();
    r << "\n## Try it\n\n```sh\n"
      << "shadowlab window --shaders shaders --stage " << a.due().front()->stage
      << (a.due().front()->tree == "legacy" ? " --glsl legacy" : "")
      << "   # watch it live; edits reload\n"
      << "shadowlab check --assignment assignment.json --shaders shaders   # your points so far\n"
      << "```\n\n"
      << "`check` grades your folder the way the instructor will: each stage against the "
         "ray-traced\n"
      << "truth, from several cameras, with the points of each check (some checks are graded but\n"
      << "shown only after the due date). `--diff-dir diffs` writes a picture of each check:\n"
      << "red where you draw a shadow that is not there, blue where you miss one.\n\n"
      << "## What to hand in\n\n"
      << "The `shaders` folder (or a .zip of it) with your edited files at the same places:\n";
    for (const AssignmentStage* s : a.due())
        for (const auto& f : s->files) r << "- `" << f << "`\n";
    r << "\nA stage whose file is not in your hand-in is MISSING and gets no points. Files you "
         "did\n"
      << "not change may stay in the folder.\n";
    if (!a.ownCheckReport.empty())
        r << "\nYou may also hand in the report of your own check, named `" << a.ownCheckReport
          << "`, at the top of\nthe folder beside the stage folders (`check` writes outputs "
             "outside the folder it grades):\n\n```sh\n"
          << "shadowlab check --assignment assignment.json --shaders shaders --report "
          << a.ownCheckReport << "\ncp " << a.ownCheckReport << " shaders/\n```\n\n"
          << "It earns nothing and changes nothing (every check is run again); your feedback "
             "page\nsays where your machine's verdicts differ from the grader's.\n";
    return r.str();
}

// Every regular file under `root`/`folder` ("" = all of `root`): its path relative to `root`
// and its text. A file that cannot be read, or a tree that cannot be listed, is an error.
std::vector<StudentFile> treeFiles(const std::string& root, const std::string& folder) {
    std::vector<StudentFile> out;
    std::error_code ec;
    fs::path base = folder.empty() ? fs::path(root) : fs::path(root) / folder;
    if (!fs::is_directory(base, ec)) return out;
    for (auto it = fs::recursive_directory_iterator(base, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        if (!it->is_regular_file(ec) || it->is_symlink(ec)) continue;
        std::string text, path = it->path().string();
        std::string err = readRegularFile(path, kMaxShaderBytes, text);
        if (!err.empty()) throw UsageError("release: " + printableName(path) + ": " + err);
        out.push_back({fs::relative(it->path(), root).string(), text});
    }
    if (ec) throw UsageError("release: cannot list " + printableName(base.string()));
    return out;
}

std::string studentEditionNote() {
    return "# The student edition\n\n"
           "In these shaders every part a lab asks you to write is a stub: it builds, draws a\n"
           "\"not done yet\" picture (no shadows, a grey mirror) and says in a TODO what to "
           "write.\n"
           "Write your work in a folder of your own, laid out like this one (`margin/lit.frag`),\n"
           "and run `shadowlab window --shaders DIR` or `shadowlab check --assignment A.json\n"
           "--shaders DIR`.\n";
}

}  // namespace

std::string SolutionTrees::root(const std::string& tree) const {
    if (dir.empty()) return shaderTreeRoot(tree == "legacy" ? GlslTree::Legacy : GlslTree::Core);
    return dir + (tree == "legacy" ? "/shaders_legacy" : "/shaders_core");
}

std::string SolutionTrees::describe() const {
    return dir.empty() ? "the shipped shaders" : "the solutions in " + printableName(dir);
}

SolutionTrees solutionTrees(const std::string& dir) {
    if (dir.empty()) return {};
    std::error_code ec;
    if (!fs::is_directory(dir + "/shaders_core", ec) &&
        !fs::is_directory(dir + "/shaders_legacy", ec))
        throw UsageError("--solutions " + printableName(dir) +
                         ": holds neither shaders_core/ nor shaders_legacy/ (the layout of the "
                         "shipped data: DIR/shaders_core/<stage>/lit.frag ...)");
    return {dir};
}

std::vector<std::string> markedFiles(const std::string& root, const std::string& folder) {
    std::vector<std::string> out;
    for (const StudentFile& f : treeFiles(root, folder)) {
        std::vector<std::string> solution;
        stripSolutions(f.text, printableName(root + "/" + f.rel), &solution);
        if (!solution.empty()) out.push_back(f.rel);
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<StudentFile> releasedShaders(const Assignment& a, const SolutionTrees& trees) {
    std::vector<StudentFile> out;
    for (std::size_t k = 0; k < a.stages.size(); ++k) {
        const AssignmentStage& s = a.stages[k];
        if (!s.due) continue;
        std::string root = trees.root(s.tree), path = "/stages/" + std::to_string(k) + "/files";
        for (const std::string& f : s.files) {
            std::string source = root + "/" + f, text;
            std::string err = readRegularFile(source, kMaxShaderBytes, text);
            if (!err.empty())
                throw UsageError("release: " + printableName(source) + " (" + a.at(path) +
                                 ", from " + trees.describe() + "): " + err);
            std::vector<std::string> solution;
            std::string stripped = stripSolutions(text, printableName(source), &solution);
            if (solution.empty())
                throw AssignmentError(printableName(source) +
                                      ": no BEGIN SOLUTION region: the release would hand out "
                                      "the whole solution of stage " +
                                      s.stage +
                                      " (mark the part students write, in your own trees: "
                                      "--solutions DIR)");
            out.push_back({f, stripped});
        }
    }
    return out;
}

void checkReleaseOut(const std::string& outDir) {
    // The release is never written into what it is made from (release --gradescope packs these
    // folders: a release inside them would pack itself), nor over the data tree.
    const std::string data = dataDir();
    if (liesWithin(data, outDir))
        throw UsageError("release --out " + printableName(outDir) + ": holds shadowlab's data (" +
                         printableName(data) + "): give a folder outside it");
    for (const char* top : {"src", "shaders_core", "shaders_legacy", "scenes", "scripts",
                            "slides_examples", "assignments", "cmake", "docs", "tests"})
        if (liesWithin(outDir, data + "/" + top))
            throw UsageError("release --out " + printableName(outDir) + ": lies inside " +
                             printableName(data + "/" + top) +
                             " (what the release is made from): give a folder outside it");
    std::error_code ec;
    if (fs::exists(outDir, ec) && !fs::is_empty(outDir, ec))
        throw UsageError("release --out " + printableName(outDir) +
                         ": the folder exists and is not empty (the release is written fresh)");
}

std::vector<std::string> writeRelease(const Assignment& a, const std::vector<StudentFile>& shaders,
                                      const std::string& outDir) {
    checkReleaseOut(outDir);
    std::error_code ec;
    fs::create_directories(outDir, ec);
    if (ec) throw UsageError("release --out " + printableName(outDir) + ": cannot create it");
    std::vector<std::string> written;
    for (const StudentFile& f : shaders) {
        writeText(outDir + "/shaders/" + f.rel, f.text);
        written.push_back("shaders/" + f.rel);
    }
    writeText(outDir + "/assignment.json", a.publicJson.dump(2) + "\n");
    writeText(outDir + "/README.md", studentReadme(a));
    written.push_back("assignment.json");
    written.push_back("README.md");
    return written;
}

int writeStudentEdition(const SolutionTrees& trees, const std::string& outDir) {
    int stubbed = 0;
    std::vector<StudentFile> files;  // everything checked before anything is written
    for (const char* tree : {"core", "legacy"}) {
        std::string root = trees.root(tree), top = std::string("shaders_") + tree;
        std::error_code ec;
        if (!fs::is_directory(root, ec))
            throw UsageError("release --student-edition: no " + printableName(root));
        if (fs::exists(outDir + "/" + top, ec))
            throw UsageError("release --student-edition: " + printableName(outDir + "/" + top) +
                             " exists already (the edition is written fresh)");
        for (const StudentFile& f : treeFiles(root, "")) {
            std::string stripped = stripSolutions(f.text, printableName(root + "/" + f.rel));
            stubbed += stripped != f.text;
            files.push_back({top + "/" + f.rel, stripped});
        }
        files.push_back({top + "/" + kStudentEditionNote, studentEditionNote()});
    }
    for (const StudentFile& f : files) writeText(outDir + "/" + f.rel, f.text);
    return stubbed;
}

}  // namespace sl
