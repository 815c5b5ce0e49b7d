#include "metrics/callgrind.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sl {

std::string shellQuote(const std::string& text) {
    std::string q = "'";
    for (char c : text) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

std::string callgrindCommand(const std::string& exe, const std::string& outFile,
                             const std::string& childArguments) {
    std::ostringstream c;
    c << "LP_NUM_THREADS=0 valgrind --tool=callgrind --collect-atstart=no"
      << " --callgrind-out-file=" << shellQuote(outFile) << " " << shellQuote(exe) << " "
      << childArguments;
    return c.str();
}

long long parseCallgrindTotal(const std::string& text) {
    std::istringstream lines(text);
    long long found = -1;
    for (std::string line; std::getline(lines, line);) {
        for (const char* key : {"totals:", "summary:"}) {
            std::size_t n = std::string(key).size();
            if (line.compare(0, n, key) != 0) continue;
            std::istringstream value(line.substr(n));
            long long v = -1;
            if (value >> v && v >= 0) found = std::max(found, v);
        }
    }
    return found;
}

double instructionsPerFrame(long long total, int frames) {
    if (total < 0 || frames <= 0) return NAN;
    return static_cast<double>(total) / frames;
}

}  // namespace sl
