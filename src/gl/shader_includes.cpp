#include "gl/shader_includes.h"

#include "io/files.h"

namespace sl {

namespace {

// Bounds on what one shader may pull in: far beyond any lesson's shaders, small enough that an
// include bomb or a device stops at once.
constexpr std::size_t kMaxFileBytes = 1u << 20;
constexpr std::size_t kMaxExpandedBytes = 1u << 20;  // one stage file with its includes
constexpr int kMaxIncludes = 256;                    // include expansions per stage file
constexpr int kMaxIncludeDepth = 8;
constexpr std::size_t kMaxIncludeName = 256;

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

}  // namespace

// One pass over the line: a regex here recursed once per character and overflowed the stack on a
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

namespace {

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

}  // namespace

GlslSource expandIncludes(const ShaderLibrary& lib, GlslTree tree, const std::string& relative) {
    Expanded out;
    Preprocessor(lib, tree).expand(relative, out, 0, "");
    return std::move(out);
}

}  // namespace sl
