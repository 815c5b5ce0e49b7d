#include "window/window_text.h"

#include <cctype>
#include <cstdio>
#include <sstream>

namespace sl {

std::string shotFileName(const std::string& stage, const std::string& tree, const std::string& view,
                         std::time_t seconds, int millis) {
    std::tm local{};
    localtime_r(&seconds, &local);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
    char ms[8];
    std::snprintf(ms, sizeof ms, "%03d", millis % 1000);
    return stage + "-" + tree + "-" + view + "-" + stamp + "-" + ms + ".png";
}

const std::vector<std::string>& windowHelp() {
    static const std::vector<std::string> help = {
        "0-8: stage by number    [ ]: previous / next stage (all nine, either tree)",
        "n: the stage's next lesson (settings applied)    s: split, failure beside fix",
        "g: switch the GLSL tree (core / legacy); fixed always runs legacy",
        "Tab / Shift-Tab: next / previous parameter",
        "= -: change it one step    Shift + -: ten steps (+ and _)",
        "x: reset this stage's parameters    c: reset camera and light",
        "v: next debug view    l: animate the light    left drag, arrows: orbit",
        "mouse wheel: zoom    f: full screen",
        "r: try the shaders on disk again now    p: save a PNG (./shots or --shots DIR)",
        "i: HUD compact / full / hidden    PgUp/PgDn: the full HUD or a page, scrolled",
        "h: these keys, in the picture's place    Esc: quit",
    };
    return help;
}

std::vector<std::string> nonBlankLines(const std::string& message) {
    std::vector<std::string> lines;
    std::istringstream in(message);
    for (std::string line; std::getline(in, line);)
        if (line.find_first_not_of(" \t\r") != std::string::npos) lines.push_back(line);
    return lines;
}

std::string firstErrorLine(const std::string& message) {
    const auto lines = nonBlankLines(message);
    for (const std::string& line : lines) {
        // PATH:LINE: or PATH:LINE:COLUMN: with no space in PATH
        for (std::size_t colon = line.find(':'); colon != std::string::npos;
             colon = line.find(':', colon + 1)) {
            std::size_t digits = colon + 1;
            while (digits < line.size() && std::isdigit(static_cast<unsigned char>(line[digits])))
                ++digits;
            if (digits == colon + 1 || digits >= line.size() || line[digits] != ':') continue;
            std::size_t start = line.rfind(' ', colon);
            start = start == std::string::npos ? 0 : start + 1;
            if (start == colon) continue;
            std::size_t end = digits;  // past a column too
            std::size_t column = end + 1;
            while (column < line.size() && std::isdigit(static_cast<unsigned char>(line[column])))
                ++column;
            if (column > end + 1 && column < line.size() && line[column] == ':') end = column;
            std::string place = line.substr(start, end - start);
            std::string before = line.substr(0, start), after = line.substr(end + 1);
            while (!before.empty() && (before.back() == ' ' || before.back() == ':'))
                before.pop_back();
            while (!after.empty() && after.front() == ' ') after.erase(0, 1);
            return place + ": " + (before.empty() ? "" : before + ": ") + after;
        }
    }
    return lines.empty() ? "" : lines.front();
}

std::string oneLine(const std::string& message) {
    std::string out;
    for (const std::string& line : nonBlankLines(message)) out += (out.empty() ? "" : " | ") + line;
    return out;
}

}  // namespace sl
