#include "gl/glsl_standard.h"

#include <glslang/Public/ShaderLang.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <memory>
#include <mutex>
#include <regex>
#include <sstream>

#include "gl/glsl_syntax.h"
#include "gl/shader_library.h"
#include "io/files.h"

#ifdef SHADOWLAB_GLSLANG_RESOURCES_HEADER
#include <glslang/Public/ResourceLimits.h>
#endif

namespace sl {

namespace {

constexpr std::size_t kMaxMessages = 20;  // error lines kept from one log
// Said where a driver's message would say nothing: the refusal is the standard's, on any driver.
constexpr const char* kByGlslang = "by the GLSL standard (glslang, Khronos' reference compiler)";

void initializeOnce() {
    static std::once_flag once;
    std::call_once(once, [] { glslang::InitializeProcess(); });
}

// The limits glslang checks built-in array sizes and constants against.
const TBuiltInResource& resources() {
#ifdef SHADOWLAB_GLSLANG_RESOURCES_HEADER
    return *GetDefaultResources();
#else
    // glslang 11 installs no header for its defaults (cmake/glslang.cmake): the same values,
    // set by name (the fields every glslang since 7 has), the rest left zero.
    static const TBuiltInResource limits = [] {
        TBuiltInResource r;
        std::memset(&r, 0, sizeof r);
        r.maxLights = 32;
        r.maxClipPlanes = 6;
        r.maxTextureUnits = 32;
        r.maxTextureCoords = 32;
        r.maxVertexAttribs = 64;
        r.maxVertexUniformComponents = 4096;
        r.maxVaryingFloats = 64;
        r.maxVertexTextureImageUnits = 32;
        r.maxCombinedTextureImageUnits = 80;
        r.maxTextureImageUnits = 32;
        r.maxFragmentUniformComponents = 4096;
        r.maxDrawBuffers = 32;
        r.maxVertexUniformVectors = 128;
        r.maxVaryingVectors = 8;
        r.maxFragmentUniformVectors = 16;
        r.maxVertexOutputVectors = 16;
        r.maxFragmentInputVectors = 15;
        r.minProgramTexelOffset = -8;
        r.maxProgramTexelOffset = 7;
        r.maxClipDistances = 8;
        r.maxGeometryInputComponents = 64;
        r.maxGeometryOutputComponents = 128;
        r.maxGeometryTextureImageUnits = 16;
        r.maxGeometryOutputVertices = 256;
        r.maxGeometryTotalOutputComponents = 1024;
        r.maxGeometryUniformComponents = 1024;
        r.maxGeometryVaryingComponents = 64;
        r.maxVertexAtomicCounters = 0;
        r.maxCombinedAtomicCounters = 8;
        r.maxCombinedAtomicCounterBuffers = 1;
        r.maxAtomicCounterBindings = 1;
        r.maxSamples = 4;
        r.limits.nonInductiveForLoops = true;
        r.limits.whileLoops = true;
        r.limits.doWhileLoops = true;
        r.limits.generalUniformIndexing = true;
        r.limits.generalAttributeMatrixVectorIndexing = true;
        r.limits.generalVaryingIndexing = true;
        r.limits.generalSamplerIndexing = true;
        r.limits.generalVariableIndexing = true;
        r.limits.generalConstantMatrixVectorIndexing = true;
        return r;
    }();
    return limits;
#endif
}

// The file and line behind line `index` (0-based) of an expanded source: the loader's `#line N
// S` directives replayed (GLSL before 3.30 numbers the line after `#line N` as N + 1).
std::string placeOf(const GlslSource& src, int index, int version) {
    std::istringstream in(src.text);
    std::string line;
    int source = 0, number = 1;
    for (int i = 0; std::getline(in, line) && i < index; ++i) {
        int n = 0, s = 0;
        if (std::sscanf(line.c_str(), " #line %d %d", &n, &s) == 2) {
            source = s;
            number = version >= 330 ? n : n + 1;
        } else {
            ++number;
        }
    }
    std::string file =
        source >= 0 && std::size_t(source) < src.files.size() ? src.files[source] : "?";
    return printableName(file) + ":" + std::to_string(number);
}

std::string fileOf(const GlslSource& src, int source) {
    return printableName(source >= 0 && std::size_t(source) < src.files.size()
                             ? src.files[std::size_t(source)]
                             : "source " + std::to_string(source));
}

// The #version a stage file declares (110 when none, as GLSL says), its profile word and the
// line it is on. Comments and blank lines may come before it.
struct Declared {
    bool bom = false;  // the file starts with a UTF-8 byte order mark, which no GLSL compiler reads
    bool declared = false;
    int version = 110;
    std::string profile;
    int line = 1;
};

Declared declaredVersion(const std::string& text) {
    Declared d;
    std::size_t i = 0, n = text.size();
    int line = 1;
    if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) {  // what a Windows editor saves first
        d.bom = true;
        i = 3;
    }
    while (i < n) {
        char c = text[i];
        if (c == '\n') {
            ++line;
            ++i;
        } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
            ++i;
        } else if (text.compare(i, 2, "//") == 0) {
            while (i < n && text[i] != '\n') ++i;
        } else if (text.compare(i, 2, "/*") == 0) {
            std::size_t end = text.find("*/", i + 2);
            end = end == std::string::npos ? n : end + 2;
            for (; i < end; ++i) line += text[i] == '\n';
        } else {
            break;
        }
    }
    int version = 0;
    char profile[16] = {0};
    std::string directive = text.substr(i, text.find('\n', i) - i);  // its line alone
    if (i < n && text[i] == '#' &&
        std::sscanf(directive.c_str(), "# version %d %15[a-z]", &version, profile) >= 1) {
        d.declared = true;
        d.version = version;
        d.profile = profile;
        d.line = line;
    }
    return d;
}

// What the tree's context guarantees (src/platform: legacy OpenGL 2.1 compatibility under
// OSMesa, core OpenGL 3.3): a version beyond it works on one driver and not on another.
// "" when `d` is one of them, else the error line.
std::string treeVersionError(GlslTree tree, const GlslSource& src, const Declared& d) {
    bool core = tree == GlslTree::Core;
    if (d.bom)  // named as itself: otherwise it reads as a file without #version
        return fileOf(src, 0) + ":1: error: starts with a UTF-8 byte order mark (EF BB BF)" +
               (d.declared ? " before #version" : "") + ": save the file without it";
    bool ok = core ? (d.version == 140 || d.version == 150 || d.version == 330) &&
                         (d.profile.empty() || d.profile == "core")
                   : d.version == 110 || d.version == 120;
    if (ok) return {};
    std::string declared = d.declared ? "#version " + std::to_string(d.version) +
                                            (d.profile.empty() ? "" : " " + d.profile)
                                      : "no #version (GLSL 1.10 then)";
    return fileOf(src, 0) + ":" + std::to_string(d.line) + ": error: " + declared +
           (core ? ": an OpenGL 3.3 core context guarantees #version 140, 150 or 330 core "
                   "only; the core tree's shaders declare #version 330 core"
                 : ": the legacy tree's OpenGL 2.1 context guarantees #version 110 or 120 "
                   "only; the legacy tree's shaders declare #version 120");
}

// Bytes on which compilers disagree, refused by one rule whatever this driver does: a NUL (Mesa
// ends the source there, glslang reads on) and a carriage return alone as a line end (an old Mac
// editor's; glslang then reads one long line and blames an #include). "" when there is neither.
std::string textBytesError(const GlslSource& src, int version) {
    const std::string& text = src.text;
    int line = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
        } else if (text[i] == '\0') {
            return placeOf(src, line, version) +
                   ": error: a NUL byte (0x00): GLSL source is text, and drivers differ on it "
                   "(Mesa stops reading there, glslang reads on): delete it";
        } else if (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n')) {
            return placeOf(src, line, version) +
                   ": error: a line ends in a carriage return alone (CR, an old Mac editor's "
                   "line end): save the file with LF or CRLF line ends";
        }
    }
    return {};
}

// `#pragma STDGL invariant(all)` in a fragment shader: GLSL 1.20 and 1.30-4.10 (section 4.6.1)
// make it an error; glslang lets it pass and Mesa refuses it, so it is refused here for every
// driver. Comments are skipped; "" when there is none.
std::string invariantAllError(const GlslSource& src, int version) {
    static const std::regex pragma(
        R"(^[ \t]*#[ \t]*pragma[ \t]+STDGL[ \t]+invariant[ \t]*\([ \t]*all[ \t]*\))");
    std::string code = src.text;  // comments blanked, line ends kept
    for (std::size_t i = 0; i < code.size(); ++i) {
        std::size_t end = i;
        if (code.compare(i, 2, "//") == 0)
            end = code.find('\n', i);
        else if (code.compare(i, 2, "/*") == 0)
            end = code.find("*/", i + 2) + 2;
        else
            continue;
        if (end < i || end > code.size()) end = code.size();  // unterminated
        for (std::size_t k = i; k < end; ++k)
            if (code[k] != '\n') code[k] = ' ';
        i = end == 0 ? 0 : end - 1;
    }
    std::istringstream in(code);
    std::string line;
    for (int index = 0; std::getline(in, line); ++index)
        if (std::regex_search(line.substr(0, 200), pragma))
            return placeOf(src, index, version) +
                   ": error: '#pragma STDGL invariant(all)' : not allowed in a fragment shader "
                   "(GLSL section 4.6.1; glslang lets it pass, Mesa refuses it): delete it";
    return {};
}

// glslang's message after its place in the words a student reads (the same as a driver's): its
// empty token field dropped ("'' :  syntax error" is "syntax error"), and its grammar's token names
// as the characters they stand for ("unexpected SEMICOLON" is "unexpected ';'", as Mesa writes it).
std::string plainMessage(std::string m) {
    if (m.rfind("'' :", 0) == 0) m.erase(0, 4);
    std::string out;
    for (char c : m)  // one space between words
        if (c != ' ' || (!out.empty() && out.back() != ' ')) out += c;
    static const std::pair<const char*, const char*> kTokens[] = {
        {"SEMICOLON", ";"},   {"COMMA", ","},        {"COLON", ":"},         {"DOT", "."},
        {"EQUAL", "="},       {"LEFT_PAREN", "("},   {"RIGHT_PAREN", ")"},   {"LEFT_BRACE", "{"},
        {"RIGHT_BRACE", "}"}, {"LEFT_BRACKET", "["}, {"RIGHT_BRACKET", "]"}, {"PLUS", "+"},
        {"DASH", "-"},        {"STAR", "*"},         {"SLASH", "/"},         {"PERCENT", "%"},
        {"BANG", "!"},        {"TILDE", "~"},        {"QUESTION", "?"},      {"LEFT_ANGLE", "<"},
        {"RIGHT_ANGLE", ">"}, {"VERTICAL_BAR", "|"}, {"CARET", "^"},         {"AMPERSAND", "&"},
        {"INC_OP", "++"},     {"DEC_OP", "--"},      {"LE_OP", "<="},        {"GE_OP", ">="},
        {"EQ_OP", "=="},      {"NE_OP", "!="},       {"AND_OP", "&&"},       {"OR_OP", "||"},
        {"XOR_OP", "^^"},     {"ADD_ASSIGN", "+="},  {"SUB_ASSIGN", "-="},   {"MUL_ASSIGN", "*="},
        {"DIV_ASSIGN", "/="}, {"LEFT_OP", "<<"},     {"RIGHT_OP", ">>"}};
    auto word = [](char c) { return std::isupper(static_cast<unsigned char>(c)) || c == '_'; };
    for (const auto& [name, text] : kTokens) {
        const std::string n = name;
        for (std::size_t at = out.find(n); at != std::string::npos; at = out.find(n, at + 1)) {
            const std::size_t end = at + n.size();
            if ((at > 0 && word(out[at - 1])) || (end < out.size() && word(out[end]))) continue;
            out.replace(at, n.size(), std::string("'") + text + "'");
        }
    }
    return out;
}

// glslang's "ERROR: S:L: msg" lines as "FILE:L: error: msg" (summary lines dropped).
std::vector<std::string> mappedErrors(const std::string& log, const GlslSource& src) {
    std::vector<std::string> out;
    std::istringstream in(log);
    std::string line;
    while (std::getline(in, line) && out.size() < kMaxMessages) {
        if (line.rfind("ERROR: ", 0) != 0) continue;
        std::string rest = line.substr(7);
        while (!rest.empty() && (rest.back() == ' ' || rest.back() == '\r')) rest.pop_back();
        if (rest.find("compilation errors.") != std::string::npos ||
            rest.find("'' : compilation terminated") != std::string::npos ||
            rest.find("node is still EOpNull") != std::string::npos)
            continue;
        int source = 0, number = 0, used = 0;
        if (std::sscanf(rest.c_str(), "%d:%d: %n", &source, &number, &used) == 2 && used > 0)
            out.push_back(fileOf(src, source) + ":" + std::to_string(number) +
                          ": error: " + plainMessage(rest.substr(std::size_t(used))));
        else
            out.push_back(fileOf(src, 0) + ": error: " + plainMessage(rest));
    }
    return out;
}

std::string joined(const std::vector<std::string>& lines) {
    std::string out;
    for (const auto& l : lines) out += l + "\n";
    return out;
}

struct ParsedStage {
    std::unique_ptr<glslang::TShader> shader;
    std::string tree;  // the printed syntax tree
    int version = 110;
};

ParsedStage parseStage(EShLanguage language, const char* kind, const GlslSource& src,
                       GlslTree tree) {
    const std::string header =
        fileOf(src, 0) + ": " + kind + " shader did not compile " + kByGlslang + ":\n";
    Declared declared = declaredVersion(src.text);
    std::string versionError = treeVersionError(tree, src, declared);
    if (versionError.empty()) versionError = textBytesError(src, declared.version);
    if (versionError.empty() && language == EShLangFragment)
        versionError = invariantAllError(src, declared.version);
    if (!versionError.empty()) throw ShaderError(header + versionError + "\n");
    ParsedStage p;
    p.version = declared.version;
    p.shader = std::make_unique<glslang::TShader>(language);
    const char* text = src.text.c_str();
    const int length = static_cast<int>(src.text.size());
    p.shader->setStringsWithLengths(&text, &length, 1);
    const EShMessages messages = EShMsgAST;
    bool ok = p.shader->parse(&resources(), 110, ENoProfile, false, false, messages);
    std::string log = p.shader->getInfoLog();
    std::string printed = p.shader->getInfoDebugLog();  // where glslang prints the tree
    if (!ok) {
        std::vector<std::string> errors = mappedErrors(log, src);
        if (errors.empty()) errors.push_back(fileOf(src, 0) + ": error: glslang refused it");
        throw ShaderError(header + joined(errors));
    }
    // The printed tree: its lines begin with a location ("0:12", "1:?").
    std::istringstream in(printed);
    std::string line;
    while (std::getline(in, line))
        if (!line.empty() && line[0] >= '0' && line[0] <= '9') p.tree += line + "\n";
    return p;
}

// Where a global named `name` is declared: the first line that names it outside a comment
// ("FILE:LINE"); else its first use in the tree.
std::string placeOfName(const std::string& name, const SyntaxTree& syntax, const GlslSource& src,
                        int version) {
    auto word = [](const std::string& line, std::size_t k) {
        return k < line.size() &&
               (std::isalnum(static_cast<unsigned char>(line[k])) || line[k] == '_');
    };
    std::istringstream in(src.text);
    std::string line;
    for (int i = 0; std::getline(in, line); ++i) {
        line = line.substr(0, line.find("//"));
        for (std::size_t at = line.find(name); at != std::string::npos;
             at = line.find(name, at + 1))
            if ((at == 0 || !word(line, at - 1)) && !word(line, at + name.size()))
                return placeOf(src, i, version);
    }
    for (const SyntaxTree::Global& g : syntax.globals())
        if (g.name == name && g.firstUse >= 0) {
            const SyntaxNode& n = syntax.node(g.firstUse);
            return fileOf(src, n.source) + ":" + std::to_string(n.line);
        }
    return fileOf(src, 0);
}

// glslang's link log, one message a line ("ERROR: Linking ...:" and its indented details).
std::vector<std::string> linkMessages(const std::string& log) {
    std::vector<std::string> out;
    std::istringstream in(log);
    std::string line;
    while (std::getline(in, line) && out.size() < kMaxMessages) {
        while (!line.empty() && (line.back() == ' ' || line.back() == '\r')) line.pop_back();
        if (line.rfind("ERROR: ", 0) == 0) {
            if (line.find("compilation errors") == std::string::npos) out.push_back(line.substr(7));
        } else if (!out.empty() && !line.empty() && line[0] == ' ') {
            std::size_t text = line.find_first_not_of(' ');
            out.back() += " " + line.substr(text);
        }
    }
    return out;
}

// The identifier a link message quotes last (`fragment stage: " vec4 vNormal"` -> vNormal).
// The components one global takes, from glslang's printed type ("uniform 4-element array of 3X3
// matrix of float": 36); a structure is the sum of its members; samplers take none. Saturates
// far above any limit, so a billion-element array is just "too many".
double typeComponents(const std::string& type) {
    static const std::regex array(R"((\d+)-element array of)"), matrix(R"((\d+)X(\d+) matrix)"),
        vector(R"((\d+)-component vector)");
    const std::size_t open = type.find('{');
    const std::string head = type.substr(0, open);
    double count = 1;
    for (std::sregex_iterator m(head.begin(), head.end(), array), end; m != end; ++m)
        count *= std::min(1e12, std::stod((*m)[1]));
    std::smatch m;
    if (open != std::string::npos) {
        double members = 0;
        int depth = 0;
        std::size_t start = open + 1;
        for (std::size_t i = open + 1; i < type.size() && depth >= 0; ++i) {
            if (type[i] == '{') ++depth;
            if ((type[i] == ',' && depth == 0) || (type[i] == '}' && depth-- == 0)) {
                members += typeComponents(type.substr(start, i - start));
                start = i + 1;
            }
        }
        return std::min(1e15, count * members);
    }
    if (head.find("sampler") != std::string::npos) return 0;
    if (std::regex_search(head, m, matrix)) return count * std::stod(m[1]) * std::stod(m[2]);
    if (std::regex_search(head, m, vector)) return count * std::stod(m[1]);
    return count;
}

// OpenGL 3.3's guaranteed uniform components a stage (GL_MAX_{VERTEX,FRAGMENT}_UNIFORM_COMPONENTS
// at least 1024). A program over it links on a driver that gives more and fails on one that does
// not (Mesa even runs out of memory on a huge array): refused here for every driver and both
// trees (the legacy tree's drivers give at least as many).
constexpr double kUniformComponents = 1024;

// "" when each stage's used default-block uniforms fit, else the error naming the largest.
std::string uniformComponentsError(const SyntaxTree& syntax, const GlslSource& src, int version,
                                   const char* kind) {
    double total = 0, largest = -1;
    std::string name;
    for (const SyntaxTree::Global& g : syntax.globals()) {
        if (g.firstUse < 0 || !SyntaxTree::hasWord(g.type, "uniform") ||
            g.type.find("block{") != std::string::npos)
            continue;
        const double n = typeComponents(g.type);
        total += n;
        if (n > largest) largest = n, name = g.name;
    }
    if (total <= kUniformComponents) return {};
    std::ostringstream out;
    out.precision(12);
    out << placeOfName(name, syntax, src, version) << ": error: '" << name << "' : the " << kind
        << " shader's uniforms take " << total << " components (this one " << largest
        << "); OpenGL 3.3 guarantees " << kUniformComponents
        << " a stage, so the program fails to link on a driver that gives no more";
    return out.str();
}

std::string quotedName(const std::string& message) {
    std::size_t close = message.rfind('"');
    if (close == std::string::npos || close == 0) return {};
    std::size_t end = close;
    while (end > 0 && message[end - 1] == ' ') --end;
    std::size_t start = end;
    while (start > 0 && (std::isalnum(static_cast<unsigned char>(message[start - 1])) ||
                         message[start - 1] == '_'))
        --start;
    return message.substr(start, end - start);
}

}  // namespace

StageTrees requireStandardGlsl(GlslTree tree, const GlslSource& vertex,
                               const GlslSource& fragment) {
    initializeOnce();
    ParsedStage vs = parseStage(EShLangVertex, "vertex", vertex, tree);
    ParsedStage fs = parseStage(EShLangFragment, "fragment", fragment, tree);
    const std::string both = fileOf(vertex, 0) + " + " + fileOf(fragment, 0);
    SyntaxTree vertexSyntax(vs.tree), fragmentSyntax(fs.tree);

    glslang::TProgram program;
    program.addShader(vs.shader.get());
    program.addShader(fs.shader.get());
    if (!program.link(EShMsgDefault)) {
        std::vector<std::string> lines;
        for (const std::string& m : linkMessages(program.getInfoLog())) {
            std::string name = quotedName(m);
            bool vertexOnly = m.find("Linking vertex stage") == 0;
            std::string where = name.empty() ? fileOf(vertexOnly ? vertex : fragment, 0)
                                : vertexOnly
                                    ? placeOfName(name, vertexSyntax, vertex, vs.version)
                                    : placeOfName(name, fragmentSyntax, fragment, fs.version);
            lines.push_back(where + ": error: " + m);
        }
        if (lines.empty()) lines.push_back(both + ": error: glslang could not link them");
        throw ShaderError(both + ": program did not link " + kByGlslang + ":\n" + joined(lines));
    }

    for (std::string e : {uniformComponentsError(vertexSyntax, vertex, vs.version, "vertex"),
                          uniformComponentsError(fragmentSyntax, fragment, fs.version, "fragment")})
        if (!e.empty())
            throw ShaderError(both + ": program did not link " + kByGlslang + ":\n" + e + "\n");

    // glslang links stages without asking whether each input the fragment stage reads has an
    // output to come from; the standard makes it a link error (GLSL 1.20 section 4.3.6, 3.30
    // section 4.3.4), NVIDIA's driver lets it read zero.
    std::vector<std::string> unfed;
    std::vector<SyntaxTree::Global> outputs = vertexSyntax.globals();
    for (const SyntaxTree::Global& in : fragmentSyntax.globals()) {
        if (in.firstUse < 0 || in.name.rfind("gl_", 0) == 0 || !SyntaxTree::hasWord(in.type, "in"))
            continue;
        bool fed = false;
        for (const SyntaxTree::Global& out : outputs)
            fed = fed || (out.name == in.name && SyntaxTree::hasWord(out.type, "out"));
        if (fed) continue;
        const SyntaxNode& use = fragmentSyntax.node(in.firstUse);
        unfed.push_back(fileOf(fragment, use.source) + ":" + std::to_string(use.line) +
                        ": error: '" + in.name + "' : the fragment shader reads this input, " +
                        "but the vertex shader (" + fileOf(vertex, 0) +
                        ") declares no output of that name (GLSL: a link error)");
    }
    if (!unfed.empty())
        throw ShaderError(both + ": program did not link " + kByGlslang + ":\n" + joined(unfed));
    return {vs.tree, fs.tree};
}

}  // namespace sl
