#include "gl/shader_library.h"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>

#include "gl/glsl_for_driver.h"
#include "gl/glsl_standard.h"
#include "gl/source_rules.h"
#include "io/files.h"

namespace sl {

const char* treeName(GlslTree t) {
    return t == GlslTree::Core ? "core" : "legacy";
}

ShaderError::ShaderError(const std::string& message)
    : std::runtime_error(printable(validUtf8(withShownFolders(message)))) {}

namespace {

// Bounds on what one shader may pull in: far beyond any lesson's shaders, small enough that an
// include bomb or a device stops at once.
constexpr std::size_t kMaxFileBytes = 1u << 20;
constexpr std::size_t kMaxExpandedBytes = 1u << 20;  // one stage file with its includes
constexpr int kMaxIncludes = 256;                    // include expansions per stage file
constexpr int kMaxIncludeDepth = 8;
constexpr std::size_t kMaxIncludeName = 256;

long long modificationStamp(const std::string& path) {
    struct stat st;
    if (::stat(path.c_str(), &st) != 0) return -1;
    return static_cast<long long>(st.st_mtim.tv_sec) * 1000000000LL + st.st_mtim.tv_nsec;
}

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

// Matches `#include "name"` (spaces allowed around each part) in one pass over the line; the
// name may be empty. A regex here recursed once per character and overflowed the stack on a
// line of a million spaces.
bool matchInclude(const std::string& line, std::string& name) {
    std::size_t i = 0, n = line.size();
    auto skip = [&] {
        while (i < n && isSpace(line[i])) ++i;
    };
    skip();
    if (i == n || line[i] != '#') return false;
    ++i;
    skip();
    static const char kWord[] = "include";
    if (line.compare(i, sizeof kWord - 1, kWord) != 0) return false;
    i += sizeof kWord - 1;
    std::size_t beforeSpace = i;
    skip();
    if (i == beforeSpace || i == n || line[i] != '"') return false;
    std::size_t close = line.find('"', i + 1);
    if (close == std::string::npos) return false;
    std::size_t start = i + 1;
    i = close + 1;
    skip();
    if (i != n) return false;
    name = line.substr(start, close - start);
    return true;
}

// Whether `line` is a `#line` directive (spaces allowed around '#'); `rest` is what follows.
bool matchLineDirective(const std::string& line, std::string& rest) {
    std::size_t i = 0, n = line.size();
    while (i < n && isSpace(line[i])) ++i;
    if (i == n || line[i] != '#') return false;
    ++i;
    while (i < n && isSpace(line[i])) ++i;
    if (line.compare(i, 4, "line") != 0 || (i + 4 < n && !isSpace(line[i + 4]))) return false;
    rest = line.substr(i + 4);
    return true;
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

// Source text with includes expanded; files[k] is the file behind source-string number k.
struct Expanded : GlslSource {
    int includes = 0;
};

class Preprocessor {
  public:
    Preprocessor(const ShaderLibrary& lib, GlslTree tree) : lib_(lib), tree_(tree) {}

    // `site`: "file:line" of the #include that asked for `relative` ("" for a stage file).
    void expand(const std::string& relative, Expanded& out, int depth, const std::string& site) {
        std::string where = site.empty() ? "" : " (#include at " + site + ")";
        if (depth > kMaxIncludeDepth)
            throw ShaderError(site + ": #include nested too deeply (a cycle?); at most " +
                              std::to_string(kMaxIncludeDepth) + " levels");
        ShaderLibrary::Found found = lib_.find(relative);
        if (!found.refused.empty())
            throw ShaderError(site.empty() ? found.refused : site + ": " + found.refused);
        const std::string shown = printableName(found.shown);  // one line whatever the name
        if (found.real.empty())
            throw ShaderError(shown + ": cannot read shader file (missing?)" + where);
        std::string text;
        std::string why = readRegularFile(found.real, kMaxFileBytes, text, true);
        if (!why.empty()) throw ShaderError(shown + ": cannot read shader file: " + why + where);
        int source = static_cast<int>(out.files.size());
        out.files.push_back(found.shown);
        std::size_t begin = 0;
        int number = 0;
        bool any = false;
        while (begin < text.size()) {
            std::size_t end = text.find('\n', begin);
            if (end == std::string::npos) end = text.size();
            std::string line = text.substr(begin, end - begin);
            begin = end + 1;
            ++number;
            any = any || line.find_first_not_of(" \t\r") != std::string::npos;
            std::string name, rest;
            if (matchLineDirective(line, rest)) {
                // A file's own #line may renumber its lines but not name another source string:
                // `#line 1 1` would make its errors appear to come from another file (ours).
                std::size_t at = rest.find_first_not_of(" \t\r\f\v"), end = at;
                while (end < rest.size() && rest[end] >= '0' && rest[end] <= '9') ++end;
                out.text += "#line " + (at == end ? std::string("0") : rest.substr(at, end - at)) +
                            " " + std::to_string(source) + "\n";
            } else if (matchInclude(line, name)) {
                std::string here = shown + ":" + std::to_string(number);
                if (name.size() > kMaxIncludeName)
                    throw ShaderError(here + ": #include name of " + std::to_string(name.size()) +
                                      " characters; at most " + std::to_string(kMaxIncludeName));
                if (++out.includes > kMaxIncludes)
                    throw ShaderError(here + ": more than " + std::to_string(kMaxIncludes) +
                                      " #include expansions (an include bomb?)");
                out.text += lineDirective(1, static_cast<int>(out.files.size()));
                expand(name, out, depth + 1, here);
                out.text += lineDirective(number + 1, source);
            } else {
                out.text += line;
                out.text += '\n';
            }
            if (out.text.size() > kMaxExpandedBytes)
                throw ShaderError(shown + ":" + std::to_string(number) +
                                  ": the source with its includes exceeds " +
                                  std::to_string(kMaxExpandedBytes) + " bytes");
        }
        if (!any) throw ShaderError(shown + ":1: shader file is empty");
    }

  private:
    // GLSL 1.20 numbers the line after `#line N` as N + 1; GLSL 3.30 as N.
    std::string lineDirective(int nextLine, int source) const {
        int n = tree_ == GlslTree::Legacy ? nextLine - 1 : nextLine;
        return "#line " + std::to_string(n) + " " + std::to_string(source) + "\n";
    }
    const ShaderLibrary& lib_;
    GlslTree tree_;
};

// Reads unsigned digits at `i`; false when there are none.
bool digits(const std::string& s, std::size_t& i, std::size_t& value) {
    std::size_t start = i;
    value = 0;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') {
        if (value < 100000000) value = value * 10 + std::size_t(s[i] - '0');
        ++i;
    }
    return i > start;
}

// Rewrites Mesa's first "S:L(C)" in each line into "file:L:C" (one linear pass per line).
std::string mapLog(const std::string& log, const std::vector<std::string>& files) {
    std::ostringstream out;
    std::istringstream in(log);
    std::string line;
    while (std::getline(in, line)) {
        for (std::size_t i = 0; i < line.size(); ++i) {
            if (line[i] < '0' || line[i] > '9' ||
                (i > 0 && line[i - 1] >= '0' && line[i - 1] <= '9'))
                continue;
            std::size_t j = i, s = 0, l = 0, c = 0;
            if (!digits(line, j, s) || j >= line.size() || line[j] != ':') continue;
            std::size_t lineStart = ++j;
            if (!digits(line, j, l) || j >= line.size() || line[j] != '(') continue;
            ++j;
            if (!digits(line, j, c) || j >= line.size() || line[j] != ')') continue;
            std::string file =
                s < files.size() ? printableName(files[s]) : "source " + std::to_string(s);
            line = line.substr(0, i) + file + ":" +
                   line.substr(lineStart, line.find('(', lineStart) - lineStart) + ":" +
                   std::to_string(c) + line.substr(j + 1);
            break;
        }
        if (!line.empty()) out << line << "\n";
    }
    return out.str();
}

// Compiles `driverText` (gl/glsl_for_driver.h: `src` itself, or its translation).
template <class ShaderHandle>
ShaderHandle compile(const Expanded& src, const std::string& driverText, const char* kind) {
    ShaderHandle shader = ShaderHandle::create();
    const char* text = driverText.c_str();
    glShaderSource(shader.id(), 1, &text, nullptr);
    glCompileShader(shader.id());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetShaderiv(shader.id(), GL_INFO_LOG_LENGTH, &length);
        std::string log(std::max(length, 1), '\0');
        glGetShaderInfoLog(shader.id(), length, nullptr, log.data());
        throw ShaderError(printableName(src.files[0]) + ": " + kind + " shader did not compile:\n" +
                          mapLog(log.c_str(), src.files));
    }
    return shader;
}

// Every active vertex input must be one the meshes feed (position, normal): another name would
// read an attribute array nobody enables. The student's fault, named as such (not a GL error).
void requireKnownAttributes(GLuint program, const std::string& vertexFile) {
    GLint count = 0, longest = 0;
    glGetProgramiv(program, GL_ACTIVE_ATTRIBUTES, &count);
    glGetProgramiv(program, GL_ACTIVE_ATTRIBUTE_MAX_LENGTH, &longest);
    std::vector<char> name(std::size_t(std::max(longest, 1)) + 1, '\0');
    for (GLint i = 0; i < count; ++i) {
        GLint size = 0;
        GLenum type = 0;
        GLsizei length = 0;
        glGetActiveAttrib(program, GLuint(i), GLsizei(name.size()), &length, &size, &type,
                          name.data());
        std::string attribute(name.data(), std::size_t(std::max(length, 0)));
        if (attribute.rfind("gl_", 0) == 0) continue;  // built-ins (gl_Vertex, gl_Normal)
        if (attribute == "position" || attribute == "normal") continue;
        throw ShaderError(vertexFile + ": vertex input '" + attribute +
                          "' is not supplied by the meshes (they supply 'position' and 'normal')");
    }
}

}  // namespace

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
    Preprocessor pre(*this, tree_);
    Expanded v, f;
    pre.expand(stage + "/" + pass + ".vert", v, 0, "");
    pre.expand(stage + "/" + pass + ".frag", f, 0, "");
    vert = std::move(v);
    frag = std::move(f);
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
    Expanded vert, frag;
    auto source = std::make_shared<const ProgramSource>(checkedSource(stage, pass, vert, frag));
    std::string vertText = glslForDriver(vert, ShaderKind::Vertex);
    std::string fragText = glslForDriver(frag, ShaderKind::Fragment);
    VertexShader vs = compile<VertexShader>(vert, vertText, "vertex");
    FragmentShader fs = compile<FragmentShader>(frag, fragText, "fragment");

    ProgramHandle program = ProgramHandle::create();
    glAttachShader(program.id(), vs.id());
    glAttachShader(program.id(), fs.id());
    glBindAttribLocation(program.id(), kPositionAttribute, "position");
    glBindAttribLocation(program.id(), kNormalAttribute, "normal");
    glLinkProgram(program.id());
    GLint ok = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetProgramiv(program.id(), GL_INFO_LOG_LENGTH, &length);
        std::string log(std::max(length, 1), '\0');
        glGetProgramInfoLog(program.id(), length, nullptr, log.data());
        throw ShaderError(printableName(vert.files[0]) + " + " + printableName(frag.files[0]) +
                          ": program did not link:\n" + mapLog(log.c_str(), vert.files));
    }
    glDetachShader(program.id(), vs.id());
    glDetachShader(program.id(), fs.id());
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
    // Notes about unused uniforms are for the student's own pass files, and only when they differ
    // from ours: an unmodified copy, or an overridden include alone, leaves our shader ours.
    // And only about uniforms our version of the pass declares: "no active uniform" then means
    // the student's file dropped it, not that the stage sets it for other stages' shaders too
    // (every lit pass gets shadowMatrix; margin's never used it).
    for (const std::string* f : {&vert.files[0], &frag.files[0]})
        if (fromOverlay(*f) && !sameContents(*f, root_ + "/" + f->substr(overlay_.size() + 1))) {
            std::set<std::string> ours;
            for (const char* ext : {".vert", ".frag"})
                declaredUniforms(root_, stage + "/" + pass + ext, 0, ours);
            e.program.reportMissingUniforms(std::move(ours));
        }
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

std::set<std::string> ShaderLibrary::ignoredUniforms(const std::string& stage) const {
    std::set<std::string> names;
    for (const auto& [key, entry] : programs_)
        if (key.rfind(stage + "/", 0) == 0)
            names.insert(entry.program.ignoredUniforms().begin(),
                         entry.program.ignoredUniforms().end());
    return names;
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
