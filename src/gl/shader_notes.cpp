// What the library tells about a student's programs beyond building them (gl/shader_library.h):
// uniforms their passes use but a stage never sets or sets but they never read, and what the
// stage's source rules find in their files.
#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>

#include "gl/shader_includes.h"
#include "gl/shader_library.h"
#include "gl/source_rules.h"
#include "io/files.h"

namespace sl {

namespace {

bool sameContents(const std::string& a, const std::string& b) {
    std::ifstream x(a, std::ios::binary), y(b, std::ios::binary);
    if (!x || !y) return false;
    return std::equal(std::istreambuf_iterator<char>(x), std::istreambuf_iterator<char>(),
                      std::istreambuf_iterator<char>(y), std::istreambuf_iterator<char>());
}

// The names of the uniforms our own file `relative` declares (`uniform TYPE NAME...;` lines),
// with the files it includes from our tree, a few levels deep.
void declaredUniforms(const std::string& root, const std::string& relative, int depth,
                      std::set<std::string>& names) {
    std::ifstream in(root + "/" + relative);
    for (std::string line; depth < 4 && std::getline(in, line);) {
        std::string include;
        if (matchInclude(line, include)) {
            declaredUniforms(root, include, depth + 1, names);
            continue;
        }
        std::istringstream words(line);
        std::string word, type, name;
        if (!(words >> word) || word != "uniform" || !(words >> type)) continue;
        if (type == "highp" || type == "mediump" || type == "lowp") words >> type;
        for (char c; words.get(c) && c != ';';) {  // NAME, NAME[2], NAME = value...
            if (std::isalnum(static_cast<unsigned char>(c)) || c == '_')
                name += c;
            else if (!name.empty())
                names.insert(name), name.clear();
            if (c == '[' || c == '=') break;
        }
        if (!name.empty()) names.insert(name);
    }
}

}  // namespace

void ShaderLibrary::watchOurUniforms(Program& program, const std::string& stage,
                                     const std::string& pass, const std::string& vertFile,
                                     const std::string& fragFile) const {
    auto fromOverlay = [&](const std::string& f) {
        return !overlay_.empty() && f.rfind(overlay_ + "/", 0) == 0;
    };
    // Notes about unused uniforms are for the student's own pass files, and only when they differ
    // from ours: an unmodified copy, or an overridden include alone, leaves our shader ours.
    // And only about uniforms our version of the pass declares: "no active uniform" then means
    // the student's file dropped it, not that the stage sets it for other stages' shaders too
    // (every lit pass gets shadowMatrix; margin's never used it).
    for (const std::string* f : {&vertFile, &fragFile})
        if (fromOverlay(*f) && !sameContents(*f, root_ + "/" + f->substr(overlay_.size() + 1))) {
            std::set<std::string> ours;
            for (const char* ext : {".vert", ".frag"})
                declaredUniforms(root_, stage + "/" + pass + ext, 0, ours);
            program.reportMissingUniforms(std::move(ours));
        }
}

std::vector<std::string> ShaderLibrary::unsetUniformNotes(const std::string& stage) {
    std::vector<std::string> notes;
    for (auto& [key, entry] : programs_) {
        if (key.rfind(stage + "/", 0) != 0) continue;
        for (const std::string& u : entry.program.uniformsNeverSet())
            notes.push_back("pass " + key + " (your shader) uses uniform '" + printableName(u) +
                            "', which the stage never sets in that pass: it keeps its initial "
                            "value (0 unless the shader gives one)");
    }
    return notes;
}

std::vector<std::string> ShaderLibrary::sourceNotes(const std::string& stage,
                                                    const std::vector<SourceRule>& rules) const {
    std::vector<std::string> notes;
    if (overlay_.empty() || rules.empty()) return notes;
    for (const auto& [key, entry] : programs_) {
        if (key.rfind(stage + "/", 0) != 0) continue;
        auto cached = entry.findings.find(&rules);
        if (cached == entry.findings.end())
            cached = entry.findings.emplace(&rules, sourceFindings(rules, *entry.source)).first;
        for (std::string n : cached->second)
            if (std::find(notes.begin(), notes.end(), n) == notes.end())
                notes.push_back(std::move(n));
    }
    return notes;
}

std::set<std::string> ShaderLibrary::ignoredUniforms(const std::string& stage) const {
    std::set<std::string> names;
    for (const auto& [key, entry] : programs_)
        if (key.rfind(stage + "/", 0) == 0)
            names.insert(entry.program.ignoredUniforms().begin(),
                         entry.program.ignoredUniforms().end());
    return names;
}

}  // namespace sl
