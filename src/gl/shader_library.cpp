// The library's own room: where a file is found (the overlay first, inside the two folders only),
// the program built from its checked sources, kept and reloaded. Its neighbours: the includes'
// expansion (gl/shader_includes.h), compiling and linking (gl/shader_compile.h), the standard's
// check (gl/glsl_standard.h) and the notes about a student's programs (gl/shader_notes.cpp).
#include "gl/shader_library.h"

#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>
#include <set>

#include "gl/glsl_for_driver.h"
#include "gl/glsl_standard.h"
#include "gl/shader_compile.h"
#include "gl/shader_includes.h"
#include "gl/source_rules.h"
#include "io/files.h"

namespace sl {

const char* treeName(GlslTree t) {
    return t == GlslTree::Core ? "core" : "legacy";
}

ShaderError::ShaderError(const std::string& message)
    : std::runtime_error(printable(validUtf8(withShownFolders(message)))) {}

namespace {

long long modificationStamp(const std::string& path) {
    struct stat st;
    if (::stat(path.c_str(), &st) != 0) return -1;
    return static_cast<long long>(st.st_mtim.tv_sec) * 1000000000LL + st.st_mtim.tv_nsec;
}

// `relative` with "." and "x/.." removed; "" when it is absolute, empty or climbs above the root.
std::string normalizedRelative(const std::string& relative) {
    if (relative.empty() || relative[0] == '/') return {};
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (start <= relative.size()) {
        std::size_t slash = relative.find('/', start);
        if (slash == std::string::npos) slash = relative.size();
        std::string part = relative.substr(start, slash - start);
        start = slash + 1;
        if (part.empty() || part == ".") continue;
        if (part == "..") {
            if (parts.empty()) return {};
            parts.pop_back();
        } else {
            parts.push_back(part);
        }
    }
    std::string out;
    for (const auto& part : parts) out += (out.empty() ? "" : "/") + part;
    return out;
}

std::string realPath(const std::string& path) {
    char* real = ::realpath(path.c_str(), nullptr);
    if (!real) return {};
    std::string out = real;
    std::free(real);
    return out;
}

// Whether `path` (already resolved) is `folder` or inside it, compared by whole components.
bool inside(const std::string& path, const std::string& folder) {
    if (folder.empty()) return false;
    if (folder == "/") return true;
    return path == folder || (path.size() > folder.size() && path[folder.size()] == '/' &&
                              path.compare(0, folder.size(), folder) == 0);
}

}  // namespace

ShaderLibrary::ShaderLibrary(GlslTree tree, std::string treeRoot, std::string overlay)
    : tree_(tree), root_(std::move(treeRoot)), overlay_(std::move(overlay)) {
    realRoot_ = realPath(root_);
    if (!overlay_.empty()) realOverlay_ = realPath(overlay_);
}

ShaderLibrary::Found ShaderLibrary::find(const std::string& relative) const {
    Found f;
    std::string name = normalizedRelative(relative);
    std::string allowed = "allowed: files under " +
                          (overlay_.empty() ? std::string() : printableName(overlay_) + " and ") +
                          printableName(root_);
    if (name.empty()) {
        bool absolute = !relative.empty() && relative[0] == '/';
        f.refused = "#include \"" + printableName(relative) + "\": " +
                    (absolute ? "an absolute path" : "a path that leaves the shader folder") +
                    "; " + allowed;
        return f;
    }
    f.shown = root_ + "/" + name;
    bool student = false;
    if (!overlay_.empty()) {
        std::string candidate = overlay_ + "/" + name;
        struct stat st;
        // Whatever the overlay holds under that name replaces ours and must pass the checks
        // below: a folder, a FIFO or a link out of the folder is refused, never skipped (a
        // folder named lit.frag graded as our shader would pass a submission that has none).
        if (::lstat(candidate.c_str(), &st) == 0) {
            f.shown = candidate;
            student = true;
        }
    }
    f.real = realPath(f.shown);
    if (f.real.empty()) return f;  // missing: reported as such when read
    if (!inside(f.real, realOverlay_) && !inside(f.real, realRoot_)) {
        f.refused = printableName(f.shown) +
                    ": resolves outside the shader folders (a symbolic link?); " + allowed;
        f.real.clear();
        return f;
    }
    // A hard link is a second name of a file that may live anywhere on the disk (another
    // student's, a secret): no path check can see where, so a student's file must have one name.
    struct stat st;
    if (student && ::stat(f.real.c_str(), &st) == 0 && !S_ISDIR(st.st_mode) && st.st_nlink > 1) {
        f.refused = printableName(f.shown) + ": has " + std::to_string(st.st_nlink) +
                    " hard links; a file in the shader folder must have one name (copy it)";
        f.real.clear();
    }
    return f;
}

std::string ShaderLibrary::resolve(const std::string& relative) const {
    return find(relative).shown;
}

ProgramSource ShaderLibrary::checkedSource(const std::string& stage, const std::string& pass,
                                           GlslSource& vert, GlslSource& frag) const {
    vert = expandIncludes(*this, tree_, stage + "/" + pass + ".vert");
    frag = expandIncludes(*this, tree_, stage + "/" + pass + ".frag");
    // The standard first (glslang): what it forbids is an error whatever this driver accepts.
    StageTrees trees = requireStandardGlsl(tree_, vert, frag);
    std::string overlay = overlay_;
    return {pass, std::move(trees), vert.files, frag.files, [overlay](const std::string& file) {
                return !overlay.empty() && file.rfind(overlay + "/", 0) == 0;
            }};
}

ProgramSource ShaderLibrary::standardProgram(const std::string& stage,
                                             const std::string& pass) const {
    GlslSource vert, frag;
    return checkedSource(stage, pass, vert, frag);
}

ShaderLibrary::Entry ShaderLibrary::build(const std::string& stage, const std::string& pass) const {
    GlslSource vert, frag;
    auto source = std::make_shared<const ProgramSource>(checkedSource(stage, pass, vert, frag));
    std::string vertText = glslForDriver(vert, ShaderKind::Vertex);
    std::string fragText = glslForDriver(frag, ShaderKind::Fragment);
    VertexShader vs = compileShader<VertexShader>(vert, vertText, "vertex");
    FragmentShader fs = compileShader<FragmentShader>(frag, fragText, "fragment");

    ProgramHandle program = linkShaders(vs, fs, vert, frag);
    requireKnownAttributes(program.id(), printableName(vert.files[0]));
    // The student's files among `list`, each named once, joined with " + " ("" when none).
    auto fromOverlay = [&](const std::string& f) {
        return !overlay_.empty() && f.rfind(overlay_ + "/", 0) == 0;
    };
    auto studentNames = [&](const std::vector<std::string>& list) {
        std::string names;
        std::set<std::string> named;
        for (const auto& f : list)
            if (fromOverlay(f) && named.insert(f).second)
                names += (names.empty() ? "" : " + ") + printableName(f);
        return names;
    };
    // A type mismatch names the student's file(s) of this program, or both when none is theirs.
    std::string files = studentNames({vert.files[0], frag.files[0]});
    if (files.empty()) files = printableName(vert.files[0]) + " + " + printableName(frag.files[0]);

    Entry e;
    e.program = Program(std::move(program), stage + "/" + pass);
    e.program.setOrigin(files);
    e.files = vert.files;
    e.files.insert(e.files.end(), frag.files.begin(), frag.files.end());
    e.driverTexts = {{printableName(vert.files[0]), std::move(vertText)},
                     {printableName(frag.files[0]), std::move(fragText)}};
    e.source = std::move(source);
    // Any file read from the overlay (a pass file or an include) makes it the student's program.
    e.program.setStudentFiles(studentNames(e.files));
    // Each file of ours the overlay could replace is watched at its overlay name too (missing
    // now): a student's file that appears later, re-created after a delete or by an editor's
    // rename-and-write, is then picked up by reload like an edit.
    if (!overlay_.empty())
        for (std::size_t i = 0, n = e.files.size(); i < n; ++i)
            if (e.files[i].rfind(root_ + "/", 0) == 0)
                e.files.push_back(overlay_ + "/" + e.files[i].substr(root_.size() + 1));
    for (const auto& f : e.files) e.stamps.push_back(modificationStamp(f));
    watchOurUniforms(e.program, stage, pass, vert.files[0], frag.files[0]);
    return e;
}

std::vector<std::string> ShaderLibrary::overlayFiles(const std::string& stage) const {
    std::set<std::string> names;
    if (overlay_.empty()) return {};
    for (const auto& [key, entry] : programs_) {
        if (key.rfind(stage + "/", 0) != 0) continue;
        for (std::size_t i = 0; i < entry.files.size(); ++i) {
            // Read from the overlay: the watch list also holds overlay names of ours that were
            // missing when the program was built (stamp -1).
            const std::string& f = entry.files[i];
            if (f.rfind(overlay_ + "/", 0) == 0 && entry.stamps[i] != -1)
                names.insert(f.substr(overlay_.size() + 1));
        }
    }
    return {names.begin(), names.end()};
}

Program& ShaderLibrary::program(const std::string& stage, const std::string& pass) {
    std::string key = stage + "/" + pass;
    auto it = programs_.find(key);
    if (it == programs_.end()) it = programs_.emplace(key, build(stage, pass)).first;
    return it->second.program;
}

std::vector<std::pair<std::string, std::string>> ShaderLibrary::driverTexts(
    const std::string& stage) const {
    std::vector<std::pair<std::string, std::string>> texts;
    for (const auto& [key, entry] : programs_)
        if (key.rfind(stage + "/", 0) == 0)
            texts.insert(texts.end(), entry.driverTexts.begin(), entry.driverTexts.end());
    return texts;
}

std::vector<std::string> ShaderLibrary::reload(bool force, const std::set<std::string>* stages) {
    std::vector<std::string> errors;
    for (auto& [key, entry] : programs_) {
        if (stages && !stages->count(key.substr(0, key.find('/')))) continue;
        bool changed = force;
        for (std::size_t i = 0; i < entry.files.size() && !changed; ++i)
            changed = modificationStamp(entry.files[i]) != entry.stamps[i];
        if (!changed) continue;
        std::size_t slash = key.find('/');
        try {
            entry = build(key.substr(0, slash),
                          key.substr(slash + 1));  // move-assign: old one deleted only now
        } catch (const ShaderError& e) {
            errors.push_back(e.what());
            // Remember the broken stamps so the same error is not rebuilt every frame.
            for (std::size_t i = 0; i < entry.files.size(); ++i)
                entry.stamps[i] = modificationStamp(entry.files[i]);
        }
    }
    return errors;
}

}  // namespace sl
