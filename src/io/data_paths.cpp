#include "io/data_paths.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>

namespace sl {

namespace {

// <prefix>/share/shadowlab beside an installed <prefix>/bin/shadowlab, when it holds our data.
std::string installedDataDir() {
    char exe[4096];
    ssize_t n = ::readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n <= 0) return {};
    std::string path(exe, std::size_t(n));
    std::size_t slash = path.find_last_of('/');
    if (slash == std::string::npos) return {};
    return path.substr(0, slash) + "/../share/shadowlab";
}

bool isFolder(const std::string& path) {
    struct stat st;
    return ::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

}  // namespace

std::string dataDir() {
    const char* env = std::getenv("SHADOWLAB_DATA_DIR");
    if (env && *env) return env;
    static const std::string found = [] {
        std::string installed = installedDataDir();
        if (!installed.empty() && isFolder(installed + "/shaders_core")) {
            char* real = ::realpath(installed.c_str(), nullptr);  // "prefix/share/shadowlab"
            if (real) {
                installed = real;
                std::free(real);
            }
            return installed;
        }
        // The build tree runs from the sources it was built from; an installed copy whose
        // share/ is gone must not silently fall back (the install test sets this).
        const char* noFallback = std::getenv("SHADOWLAB_NO_SOURCE_DIR");
        if (noFallback && *noFallback) return installed;
        return std::string(SHADOWLAB_SOURCE_DIR);
    }();
    return found;
}

}  // namespace sl
