#include "course/release.h"

#include <filesystem>
#include <sstream>

#include "course/class_entries.h"
#include "io/files.h"
#include "scene/scene_json.h"

namespace sl {

namespace {

std::string trimmed(const std::string& s) {
    std::size_t a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
    return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

void writeText(const std::string& path, const std::string& text) {
    std::error_code ec;
    std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
    std::string err = writeFileAtomically(path, text.data(), text.size());
    if (!err.empty()) throw UsageError("release: " + err);
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
    return r.str();
}

}  // namespace

std::string stripSolutions(const std::string& text, const std::string& origin,
                           std::vector<std::string>* solution) {
    std::istringstream in(text);
    std::ostringstream out;
    std::string line;
    int number = 0, begin = 0;
    bool inRegion = false, afterRegion = false, sawStub = false;
    std::string indent;
    auto closeRegion = [&]() {
        if (afterRegion && !sawStub) out << indent << "// TODO: write this part\n";
        afterRegion = false;
    };
    while (std::getline(in, line)) {
        ++number;
        std::string t = trimmed(line);
        auto where = [&](const std::string& what) {
            return AssignmentError(origin + ": line " + std::to_string(number) + ": " + what);
        };
        if (t == "// BEGIN SOLUTION") {
            if (inRegion)
                throw where("BEGIN SOLUTION inside the region opened on line " +
                            std::to_string(begin));
            closeRegion();
            inRegion = true;
            begin = number;
            indent = line.substr(0, line.find('/'));
            continue;
        }
        if (t == "// END SOLUTION") {
            if (!inRegion) throw where("END SOLUTION without a BEGIN SOLUTION");
            inRegion = false;
            afterRegion = true;
            sawStub = false;
            continue;
        }
        if (inRegion) {
            if (solution) solution->push_back(line);
            continue;
        }
        if (t.rfind("// STUB:", 0) == 0) {
            if (!afterRegion) throw where("a STUB line not right after an END SOLUTION");
            std::string code = t.substr(8);
            if (!code.empty() && code[0] == ' ') code.erase(0, 1);
            out << line.substr(0, line.find('/')) << code << "\n";
            sawStub = true;
            continue;
        }
        closeRegion();
        out << line << "\n";
    }
    if (inRegion)
        throw AssignmentError(origin + ": line " + std::to_string(begin) +
                              ": BEGIN SOLUTION is never closed");
    closeRegion();
    std::string result = out.str();
    if (!text.empty() && text.back() != '\n' && !result.empty()) result.pop_back();
    return result;
}

std::vector<std::string> writeRelease(const Assignment& a, const std::string& assignmentPath,
                                      const std::string& outDir) {
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
    if (std::filesystem::exists(outDir, ec) && !std::filesystem::is_empty(outDir, ec))
        throw UsageError("release --out " + printableName(outDir) +
                         ": the folder exists and is not empty (the release is written fresh)");
    std::filesystem::create_directories(outDir, ec);
    if (ec) throw UsageError("release --out " + printableName(outDir) + ": cannot create it");
    (void)assignmentPath;
    std::vector<std::string> written;
    for (const AssignmentStage* s : a.due())
        for (const std::string& f : s->files) {
            std::string source =
                shaderTreeRoot(s->tree == "legacy" ? GlslTree::Legacy : GlslTree::Core) + "/" + f;
            std::string text;
            std::string err = readRegularFile(source, 1u << 20, text);
            if (!err.empty()) throw UsageError("release: " + source + ": " + err);
            std::vector<std::string> solution;
            std::string stripped = stripSolutions(text, source, &solution);
            if (solution.empty())
                throw AssignmentError(source +
                                      ": no BEGIN SOLUTION region: the release would hand out the "
                                      "whole solution of stage " +
                                      s->stage);
            writeText(outDir + "/shaders/" + f, stripped);
            written.push_back("shaders/" + f);
        }
    writeText(outDir + "/assignment.json", a.publicJson.dump(2) + "\n");
    writeText(outDir + "/README.md", studentReadme(a));
    written.push_back("assignment.json");
    written.push_back("README.md");
    return written;
}

}  // namespace sl
