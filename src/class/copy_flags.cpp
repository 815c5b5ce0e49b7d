#include "class/copy_flags.h"

#include <algorithm>
#include <cctype>
#include <set>

#include "class/copy_pairs.h"
#include "io/files.h"

namespace sl {

namespace {

// Words that keep their spelling: GLSL's keywords, types and qualifiers, its built-in functions
// and the preprocessor's words. Anything else is a name the author chose.
const std::set<std::string>& keptWords() {
    static const std::set<std::string> words = {
        // keywords, qualifiers, types
        "attribute", "const", "uniform", "varying", "layout", "centroid", "flat", "smooth",
        "noperspective", "break", "continue", "do", "for", "while", "switch", "case", "default",
        "if", "else", "in", "out", "inout", "float", "double", "int", "uint", "void", "bool",
        "true", "false", "invariant", "discard", "return", "struct", "precision", "highp",
        "mediump", "lowp", "location", "binding", "std140", "mat2", "mat3", "mat4", "mat2x2",
        "mat2x3", "mat2x4", "mat3x2", "mat3x3", "mat3x4", "mat4x2", "mat4x3", "mat4x4", "vec2",
        "vec3", "vec4", "ivec2", "ivec3", "ivec4", "uvec2", "uvec3", "uvec4", "bvec2", "bvec3",
        "bvec4", "dvec2", "dvec3", "dvec4", "sampler1D", "sampler2D", "sampler3D", "samplerCube",
        "sampler1DShadow", "sampler2DShadow", "samplerCubeShadow", "sampler2DArray",
        "sampler2DArrayShadow", "sampler2DRect", "sampler2DRectShadow", "isampler2D", "usampler2D",
        // built-in functions
        "radians", "degrees", "sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh",
        "pow", "exp", "log", "exp2", "log2", "sqrt", "inversesqrt", "abs", "sign", "floor", "ceil",
        "fract", "trunc", "round", "roundEven", "mod", "modf", "min", "max", "clamp", "mix", "step",
        "smoothstep", "isnan", "isinf", "length", "distance", "dot", "cross", "normalize",
        "faceforward", "reflect", "refract", "matrixCompMult", "outerProduct", "transpose",
        "inverse", "determinant", "lessThan", "lessThanEqual", "greaterThan", "greaterThanEqual",
        "equal", "notEqual", "any", "all", "not", "texture", "textureProj", "textureLod",
        "textureOffset", "textureGrad", "texelFetch", "textureSize", "textureProjLod", "texture1D",
        "texture2D", "texture3D", "textureCube", "texture2DProj", "texture2DLod", "shadow1D",
        "shadow2D", "shadow2DProj", "dFdx", "dFdy", "fwidth",
        // the preprocessor
        "version", "core", "compatibility", "define", "undef", "ifdef", "ifndef", "elif", "endif",
        "include", "extension", "enable", "require", "warn", "disable", "pragma", "line", "error",
        "defined"};
    return words;
}

bool isNameStart(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}
bool isNameChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

}  // namespace

std::vector<std::string> normalizedTokens(const std::string& s) {
    static const char* const kLongOps[] = {
        "<<=", ">>=", "++", "--", "<<", ">>", "<=", ">=", "==", "!=", "&&",
        "||",  "^^",  "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^="};
    std::vector<std::string> out;
    std::map<std::string, std::string> names;
    std::size_t i = 0;
    while (i < s.size()) {
        char c = s[i];
        if (std::isspace(static_cast<unsigned char>(c)) || c == '\\') {
            ++i;  // a backslash only continues a line
        } else if (s.compare(i, 2, "//") == 0) {
            while (i < s.size() && s[i] != '\n') ++i;
        } else if (s.compare(i, 2, "/*") == 0) {
            std::size_t end = s.find("*/", i + 2);
            i = end == std::string::npos ? s.size() : end + 2;
        } else if (isNameStart(c)) {
            std::size_t b = i;
            while (i < s.size() && isNameChar(s[i])) ++i;
            std::string word = s.substr(b, i - b);
            if (keptWords().count(word) || word.rfind("gl_", 0) == 0) {
                out.push_back(word);
            } else {
                auto it = names.emplace(word, "$" + std::to_string(names.size())).first;
                out.push_back(it->second);
            }
        } else if (std::isdigit(static_cast<unsigned char>(c)) ||
                   (c == '.' && i + 1 < s.size() &&
                    std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
            std::size_t b = i;
            while (i < s.size() &&
                   (isNameChar(s[i]) || s[i] == '.' ||
                    ((s[i] == '-' || s[i] == '+') && (s[i - 1] == 'e' || s[i - 1] == 'E'))))
                ++i;
            out.push_back(s.substr(b, i - b));
        } else {
            std::size_t len = 1;
            for (const char* op : kLongOps)
                if (s.compare(i, std::char_traits<char>::length(op), op) == 0) {
                    len = std::char_traits<char>::length(op);
                    break;
                }
            out.push_back(s.substr(i, len));
            i += len;
        }
    }
    return out;
}

std::vector<CopyFlag> findCopies(const std::vector<HandInFiles>& handIns,
                                 const std::map<std::string, std::string>& solutions,
                                 const std::map<std::string, std::string>& starters) {
    std::set<std::string> fileNames;
    for (const HandInFiles& h : handIns)
        for (const auto& f : h.files) fileNames.insert(f.first);
    std::vector<CopyFlag> out;
    for (const std::string& file : fileNames) {
        std::vector<std::string> starter, solution;
        if (auto it = starters.find(file); it != starters.end())
            starter = normalizedTokens(it->second);
        if (auto it = solutions.find(file); it != solutions.end())
            solution = normalizedTokens(it->second);
        for (const HandInFiles& h : handIns) {
            auto it = h.files.find(file);
            if (it == h.files.end()) continue;
            std::vector<std::string> tokens = normalizedTokens(it->second);
            if (tokens.empty() || tokens == starter) continue;
            if (!solution.empty() && tokens == solution) out.push_back({h.name, file, ""});
        }
    }
    // Classmates: only a pair sharing at least kCopyShareFlagged of its written due code (short
    // natural code is written the same by honest students); per student and file, the others.
    std::map<std::pair<std::string, std::string>, std::vector<std::string>> others;
    for (const CopyPair& p : copyPairs(handIns, starters)) {
        if (p.share < kCopyShareFlagged) break;  // ranked: the rest are below too
        for (const std::string& file : p.files) {
            others[{p.a, file}].push_back(p.b);
            others[{p.b, file}].push_back(p.a);
        }
    }
    for (auto& [who, names] : others) {  // five named, then a count
        std::sort(names.begin(), names.end());
        std::string list;
        for (std::size_t k = 0; k < names.size() && k < 5; ++k)
            list += (list.empty() ? "" : ", ") + escapedName(names[k]);  // as pages name them
        if (names.size() > 5) list += " and " + std::to_string(names.size() - 5) + " more";
        out.push_back({who.first, who.second, list});
    }
    return out;
}

}  // namespace sl
