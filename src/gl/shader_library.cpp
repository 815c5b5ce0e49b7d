#include "gl/shader_library.h"

#include <sys/stat.h>

#include <fstream>
#include <regex>
#include <sstream>

namespace sl {

const char* treeName(GlslTree t) { return t == GlslTree::Core ? "core" : "legacy"; }

namespace {

bool fileExists(const std::string& path) {
    struct stat st;
    return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

long long modificationStamp(const std::string& path) {
    struct stat st;
    if (::stat(path.c_str(), &st) != 0) return -1;
    return static_cast<long long>(st.st_mtim.tv_sec) * 1000000000LL + st.st_mtim.tv_nsec;
}

// Source text with includes expanded; files[k] is the file behind source-string number k.
struct Expanded {
    std::string text;
    std::vector<std::string> files;
};

class Preprocessor {
public:
    Preprocessor(const ShaderLibrary& lib, GlslTree tree) : lib_(lib), tree_(tree) {}

    void expand(const std::string& relative, Expanded& out, int depth) {
        std::string path = lib_.resolve(relative);
        if (depth > 8) throw ShaderError(path + ": #include nested too deeply (a cycle?)");
        std::ifstream in(path);
        if (!in) throw ShaderError(path + ": cannot read shader file (missing?)");
        int source = static_cast<int>(out.files.size());
        out.files.push_back(path);
        std::string line;
        int number = 0;
        bool any = false;
        static const std::regex include(R"(^\s*#\s*include\s+"([^"]+)\"\s*$)");
        while (std::getline(in, line)) {
            ++number;
            any = any || line.find_first_not_of(" \t\r") != std::string::npos;
            std::smatch m;
            if (std::regex_match(line, m, include)) {
                out.text += lineDirective(1, static_cast<int>(out.files.size()));
                expand(m[1].str(), out, depth + 1);
                out.text += lineDirective(number + 1, source);
                continue;
            }
            out.text += line + "\n";
        }
        if (!any) throw ShaderError(path + ":1: shader file is empty");
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

// Rewrites Mesa's "S:L(C): message" into "file:L:C: message".
std::string mapLog(const std::string& log, const std::vector<std::string>& files) {
    static const std::regex where(R"((\d+):(\d+)\((\d+)\))");
    std::ostringstream out;
    std::istringstream in(log);
    std::string line;
    while (std::getline(in, line)) {
        std::smatch m;
        if (std::regex_search(line, m, where)) {
            std::size_t s = std::stoul(m[1].str());
            std::string file = s < files.size() ? files[s] : "source " + m[1].str();
            line = m.prefix().str() + file + ":" + m[2].str() + ":" + m[3].str() + m.suffix().str();
        }
        if (!line.empty()) out << line << "\n";
    }
    return out.str();
}

template <class ShaderHandle>
ShaderHandle compile(const Expanded& src, const char* kind) {
    ShaderHandle shader = ShaderHandle::create();
    const char* text = src.text.c_str();
    glShaderSource(shader.id(), 1, &text, nullptr);
    glCompileShader(shader.id());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetShaderiv(shader.id(), GL_INFO_LOG_LENGTH, &length);
        std::string log(std::max(length, 1), '\0');
        glGetShaderInfoLog(shader.id(), length, nullptr, log.data());
        throw ShaderError(src.files[0] + ": " + kind + " shader did not compile:\n" +
                          mapLog(log.c_str(), src.files));
    }
    return shader;
}

}  // namespace

ShaderLibrary::ShaderLibrary(GlslTree tree, std::string treeRoot, std::string overlay)
    : tree_(tree), root_(std::move(treeRoot)), overlay_(std::move(overlay)) {}

std::string ShaderLibrary::resolve(const std::string& relative) const {
    if (!overlay_.empty()) {
        std::string candidate = overlay_ + "/" + relative;
        if (fileExists(candidate)) return candidate;
    }
    return root_ + "/" + relative;
}

ShaderLibrary::Entry ShaderLibrary::build(const std::string& stage, const std::string& pass) const {
    Preprocessor pre(*this, tree_);
    Expanded vert, frag;
    pre.expand(stage + "/" + pass + ".vert", vert, 0);
    pre.expand(stage + "/" + pass + ".frag", frag, 0);
    VertexShader vs = compile<VertexShader>(vert, "vertex");
    FragmentShader fs = compile<FragmentShader>(frag, "fragment");

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
        throw ShaderError(vert.files[0] + " + " + frag.files[0] + ": program did not link:\n" +
                          mapLog(log.c_str(), vert.files));
    }
    glDetachShader(program.id(), vs.id());
    glDetachShader(program.id(), fs.id());

    Entry e;
    e.program = Program(std::move(program), stage + "/" + pass);
    e.files = vert.files;
    e.files.insert(e.files.end(), frag.files.begin(), frag.files.end());
    for (const auto& f : e.files) {
        e.stamps.push_back(modificationStamp(f));
        if (!overlay_.empty() && f.rfind(overlay_ + "/", 0) == 0)
            e.program.reportMissingUniforms(true);
    }
    return e;
}

Program& ShaderLibrary::program(const std::string& stage, const std::string& pass) {
    std::string key = stage + "/" + pass;
    auto it = programs_.find(key);
    if (it == programs_.end()) it = programs_.emplace(key, build(stage, pass)).first;
    return it->second.program;
}

std::vector<std::string> ShaderLibrary::reload(bool force) {
    std::vector<std::string> errors;
    for (auto& [key, entry] : programs_) {
        bool changed = force;
        for (std::size_t i = 0; i < entry.files.size() && !changed; ++i)
            changed = modificationStamp(entry.files[i]) != entry.stamps[i];
        if (!changed) continue;
        std::size_t slash = key.find('/');
        try {
            entry = build(key.substr(0, slash), key.substr(slash + 1));  // move-assign: old one deleted only now
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
