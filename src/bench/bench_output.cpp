#include "bench/bench_output.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "gl/gl.h"
#include "io/files.h"
#include "io/usage_error.h"

namespace sl {

void Table::add(std::vector<std::string> row) {
    if (row.size() != columns.size())
        throw std::logic_error("table row has " + std::to_string(row.size()) + " cells for " +
                               std::to_string(columns.size()) + " columns");
    rows.push_back(std::move(row));
}

std::string Table::csv() const {
    auto cell = [](const std::string& c) {
        if (c.find_first_of(",\"\n") == std::string::npos) return c;
        std::string q = "\"";
        for (char ch : c) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
        return q + "\"";
    };
    std::ostringstream out;
    for (std::size_t k = 0; k < columns.size(); ++k) out << (k ? "," : "") << cell(columns[k]);
    out << "\n";
    for (const auto& row : rows) {
        for (std::size_t k = 0; k < row.size(); ++k) out << (k ? "," : "") << cell(row[k]);
        out << "\n";
    }
    return out.str();
}

std::string num(double value, int digits) {
    if (std::isnan(value)) return "na";
    char text[64];
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    return text;
}

std::string gnuplotBlocks(const std::vector<Series>& series) {
    std::ostringstream out;
    bool first = true;
    for (const Series& s : series) {
        if (s.xs.empty()) continue;
        if (!first) out << "\n\n";
        first = false;
        out << "\"" << s.title << "\" \"\"\n";
        bool bars = s.lo.size() == s.xs.size() && s.hi.size() == s.xs.size();
        for (std::size_t k = 0; k < s.xs.size() && k < s.ys.size(); ++k) {
            out << num(s.xs[k], 8) << " " << num(s.ys[k], 8);
            if (bars) out << " " << num(s.lo[k], 8) << " " << num(s.hi[k], 8);
            out << "\n";
        }
    }
    return out.str();
}

std::string runGnuplot(const std::string& dir, const std::string& scriptPath,
                       const std::string& script) {
    std::string err = writeTextFile(scriptPath, script);
    if (!err.empty()) return err;
    if (std::system("command -v gnuplot >/dev/null 2>&1") != 0)
        return "gnuplot is not installed (apt-get install gnuplot-nox): tables written, charts "
               "skipped";
    std::string command =
        "cd '" + dir + "' && gnuplot '" + std::filesystem::absolute(scriptPath).string() + "' 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return "could not start gnuplot";
    std::string output;
    char buffer[256];
    while (std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
    int status = pclose(pipe);
    if (status != 0) {
        std::string shown;  // gnuplot's message: the last non-empty lines, on one line
        std::istringstream lines(output);
        for (std::string l; std::getline(lines, l);)
            if (!l.empty()) shown += (shown.empty() ? "" : " | ") + l;
        return "gnuplot failed (" + scriptPath + "): " + shown.substr(0, 300);
    }
    return "";
}

void makeOutputDir(const std::string& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir))
        throw UsageError("--out: cannot create the folder '" + dir + "'" +
                         (ec ? " (" + ec.message() + ")" : ""));
}

void checkOutputPath(const std::string& option, const std::string& path) {
    if (std::string why = outputPathProblem(path); !why.empty())
        throw UsageError(option + ": " + why);
}

}  // namespace sl
