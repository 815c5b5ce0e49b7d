// The loop budget's text (gl/loop_guard.h): a mechanical edit of SPIRV-Cross's ESSL, whose layout
// is its own and fixed (one statement a line, a body's brace on the line after its loop).
#include "gl/loop_guard.h"

#include <regex>
#include <sstream>
#include <vector>

namespace sl {

LoopBudgetSpent::LoopBudgetSpent(const std::string& file)
    : std::runtime_error(file + ": error: a loop ran past " + std::to_string(kLoopBudget) +
                         " iterations in one invocation and was stopped (the browser's loop "
                         "budget; docs/web.md)") {}

namespace {

std::vector<std::string> linesOf(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

std::string trimmed(const std::string& line) {
    const auto first = line.find_first_not_of(" \t");
    return first == std::string::npos ? "" : line.substr(first);
}

bool opensLoop(const std::string& statement) {
    return statement.rfind("for (", 0) == 0 || statement.rfind("while (", 0) == 0 ||
           statement == "do";
}

// The probe's write: "NAME = TYPE(1.0);" for a float output at location 0, "" when that output
// is not float (no probe), or the declaration of our own when the shader has none there.
struct ProbeOutput {
    bool probe = true;
    std::string declaration;  // added to the shader ("" when its own output is used)
    std::string write;
};

ProbeOutput probeOutput(const std::vector<std::string>& lines) {
    static const std::regex location0(R"(^layout\(location = 0\) out .*)");
    static const std::regex floatOutput(
        R"(^layout\(location = 0\) out (?:(?:lowp|mediump|highp) )?(float|vec[234]) (\w+);$)");
    for (const std::string& line : lines) {
        if (!std::regex_match(line, location0)) continue;
        std::smatch m;
        if (!std::regex_match(line, m, floatOutput)) return {false, "", ""};
        return {true, "", m[2].str() + " = " + m[1].str() + "(1.0);"};
    }
    return {true, "layout(location = 0) out highp vec4 sl_loopMarker;",
            "sl_loopMarker = vec4(1.0);"};
}

}  // namespace

std::string guardLoops(const std::string& essl, bool fragment, const std::string& file) {
    std::vector<std::string> lines = linesOf(essl);
    const std::string budget = std::to_string(kLoopBudget);
    std::vector<std::string> out;
    bool loops = false, mainFound = false;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string statement = trimmed(lines[i]);
        if (fragment && lines[i] == "void main()") {
            out.push_back("void sl_studentMain()");
            mainFound = true;
            continue;
        }
        out.push_back(lines[i]);
        if (!opensLoop(statement)) continue;
        if (i + 1 >= lines.size() || trimmed(lines[i + 1]) != "{")
            throw std::runtime_error(file + ": error: the page could not guard the loop `" +
                                     statement + "` of its translation (docs/web.md)");
        out.push_back(lines[++i]);
        const std::string indent = lines[i].substr(0, lines[i].find('{'));
        out.push_back(indent + "    if (sl_loopSpent()) break;");
        loops = true;
    }
    if (!loops) return essl;

    const ProbeOutput probe =
        fragment && mainFound ? probeOutput(lines) : ProbeOutput{false, "", ""};
    std::vector<std::string> header = {kLoopGuardLine + file,
                                       "// every loop iteration of an invocation counts; past " +
                                           budget + " the loops stop and the page says so",
                                       "highp int sl_loops = 0;",
                                       "bool sl_loopSpent()",
                                       "{",
                                       "    sl_loops += 1;",
                                       "    return sl_loops > " + budget + ";",
                                       "}"};
    if (probe.probe) {
        if (!probe.declaration.empty()) header.insert(header.begin() + 2, probe.declaration);
        header.insert(header.begin() + 2, std::string("uniform bool ") + kLoopProbe + ";");
    }
    // After the #version, #extension and precision lines, before anything that could loop.
    std::size_t at = 0;
    while (at < out.size() && (out[at].rfind("#", 0) == 0 || out[at].rfind("precision ", 0) == 0))
        ++at;
    out.insert(out.begin() + static_cast<long>(at), header.begin(), header.end());
    if (fragment && mainFound) {
        // main as it was, then the probe's answer (kLoopProbe is false in every other draw).
        for (std::string line : {"", "void main()", "{", "    sl_studentMain();"})
            out.push_back(line);
        if (probe.probe) {
            out.push_back(std::string("    if (") + kLoopProbe + ")");
            out.push_back("    {");
            out.push_back("        if (sl_loops <= " + budget + ") discard;");
            out.push_back("        " + probe.write);
            out.push_back("    }");
        }
        out.push_back("}");
    }
    std::string text;
    for (const std::string& line : out) text += line + "\n";
    return text;
}

}  // namespace sl
