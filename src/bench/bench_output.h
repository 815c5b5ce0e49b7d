// Writing what `bench` and `sweep` measured: CSV tables, gnuplot data blocks and charts, and a
// line naming the machine, which goes beside every figure.
#pragma once

#include <string>
#include <vector>

#include "gl/machine.h"  // machineLine(), beside every figure

namespace sl {

// A table with named columns; every cell is text (numbers formatted by `num`). Written as CSV.
struct Table {
    std::vector<std::string> columns;
    std::vector<std::vector<std::string>> rows;
    void add(std::vector<std::string> row);  // throws std::logic_error on a wrong cell count
    std::string csv() const;
};

// A number for a table: "na" for NaN (a figure that does not apply), else up to `digits`
// significant digits.
std::string num(double value, int digits = 4);

// One chart line: a title and its (x, y) points, optionally with an error bar per point (lo, hi:
// the quartiles of the axis that was timed).
struct Series {
    std::string title;
    std::vector<double> xs, ys;
    std::vector<double> lo, hi;  // empty, or one per point
};

// gnuplot data: one block per series, headed by its quoted title, blocks separated by two blank
// lines (so `index i` picks one and `columnheader(1)` titles it). Empty series are skipped. With
// error bars the lines have four columns: x y lo hi.
std::string gnuplotBlocks(const std::vector<Series>& series);

// Runs gnuplot on `script` (written beside the charts as `scriptPath`) in `dir`. Returns "" or a
// one-line reason (gnuplot missing or failing); charts are an extra, the tables stand alone.
std::string runGnuplot(const std::string& dir, const std::string& scriptPath,
                       const std::string& script);

// Creates `dir` (and its parents) if missing; throws UsageError when it cannot.
void makeOutputDir(const std::string& dir);

// Before any GL work: throws UsageError("OPTION: cannot write 'PATH': why") unless `path` can be
// written as an output file (its folder exists; it is not a folder, device, symlink or
// read-only file). Every output option (--out, --report, --diff, --junit...) goes through it.
void checkOutputPath(const std::string& option, const std::string& path);

}  // namespace sl
