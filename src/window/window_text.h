// Words the window shows and writes: shot file names, the help, error lines (the views' names
// and legends are lecture/hud_text.h's, the page's too). Plain functions, unit-tested without a
// window.
#pragma once

#include <ctime>
#include <string>
#include <vector>

#include "lecture/hud_text.h"

namespace sl {

// `<stage>-<tree>-<view>-<YYYYmmdd-HHMMSS-mmm>.png`, from local time `seconds` and `millis`.
std::string shotFileName(const std::string& stage, const std::string& tree, const std::string& view,
                         std::time_t seconds, int millis);

// Every key the window knows, one line each ("key: what it does").
const std::vector<std::string>& windowHelp();

// The lines of a message that hold more than blanks.
std::vector<std::string> nonBlankLines(const std::string& message);

// Joins a multi-line message into one line (" | " between its lines), for the terminal.
std::string oneLine(const std::string& message);

// The line of a shader message a student reads first: the first that names a file and a line
// ("mine/margin/lit.frag:12:5: error: syntax error, unexpected '+'"), its place put first when
// a driver writes it later in the line ("ERROR: mine/x.frag:3: ..."); else the message's first
// line (a loop refused names its file there).
std::string firstErrorLine(const std::string& message);

}  // namespace sl
