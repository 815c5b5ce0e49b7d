#include "app/mirror_figure.h"

#include <cstdlib>
#include <filesystem>
#include <vector>

#include "bench/bench_output.h"
#include "metrics/mirror_figure.h"

namespace sl {

std::string writeMirrorFigure(const std::string& path, const MirrorTopView& view) {
    namespace fs = std::filesystem;
    std::string pattern = (fs::temp_directory_path() / "shadowlab-figure-XXXXXX").string();
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    if (!::mkdtemp(buffer.data())) return "cannot create a temporary folder for the gnuplot script";
    std::string dir = buffer.data();
    std::string partial = fs::absolute(path).string() + ".tmp";
    std::string err = runGnuplot(dir, dir + "/mirror-figure.gp", mirrorFigureScript(view, partial));
    std::error_code ec;
    fs::remove_all(dir, ec);
    if (err.empty() && !fs::exists(partial)) err = "gnuplot wrote no picture to " + partial;
    if (err.empty()) {
        fs::rename(partial, path, ec);
        if (ec) err = "cannot write " + path + ": " + ec.message();
    }
    if (!err.empty()) fs::remove(partial, ec);
    return err;
}

}  // namespace sl
