// The line each value of a JSON text starts on, by its JSON pointer ("/stages/2/points"), so a
// data file's errors can name the path and the line of what is wrong (nlohmann's parsed values
// do not keep their positions).
#pragma once

#include <map>
#include <string>

namespace sl {

// Every value's JSON pointer -> its 1-based line. The text must already parse as JSON; on text
// that does not, the map holds what was read before the fault.
// With `numbers`, every number's JSON pointer -> its text as written ("1e400").
std::map<std::string, int> jsonValueLines(const std::string& text,
                                          std::map<std::string, std::string>* numbers = nullptr);

}  // namespace sl
