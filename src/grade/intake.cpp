#include "grade/intake.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>

#include "io/content_hash.h"
#include "io/files.h"
#include "stages/registry.h"
#include "stages/request.h"

namespace sl {

namespace {

// The loader's own bounds (src/gl/shader_library.cpp): no shader file above 1 MiB is read. A
// submission is a handful of shaders; these keep a hostile one (a million files, a deep tree, a
// disc image) from costing more than a moment.
constexpr std::size_t kMaxFileBytes = kIntakeLimits.fileBytes;
constexpr std::size_t kMaxTotalBytes = kIntakeLimits.totalBytes;
constexpr int kMaxEntries = kIntakeLimits.entries;
constexpr int kMaxDepth = 12;
constexpr int kMaxWrappers = 3;  // lone folders descended (jdoe_lab4/lab4/...)
constexpr std::size_t kMaxNotes = 12;

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

bool endsWith(const std::string& s, const std::string& tail) {
    return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

struct Fd {
    int fd = -1;
    explicit Fd(int f) : fd(f) {}
    ~Fd() {
        if (fd >= 0) ::close(fd);
    }
    Fd(const Fd&) = delete;
    Fd& operator=(const Fd&) = delete;
};

// The names in the folder `fd` (not consumed), junk left out, sorted; `entries` counts every one.
std::vector<std::string> listFolder(int fd, int& entries, const std::string& shown) {
    int copy = ::dup(fd);
    if (copy < 0) throw IntakeError(shown + ": cannot read: " + std::strerror(errno));
    DIR* dir = ::fdopendir(copy);
    if (!dir) {
        ::close(copy);
        throw IntakeError(shown + ": cannot read: " + std::strerror(errno));
    }
    ::rewinddir(dir);
    std::vector<std::string> names;
    while (dirent* e = ::readdir(dir)) {
        std::string name = e->d_name;
        if (name == "." || name == "..") continue;
        if (++entries > kMaxEntries) {
            ::closedir(dir);
            throw IntakeError(shown + ": more than " + std::to_string(kMaxEntries) +
                              " files and folders; a submission is a few shader files");
        }
        if (!isJunkName(name)) names.push_back(name);
    }
    ::closedir(dir);
    std::sort(names.begin(), names.end());
    return names;
}

struct Walk {
    std::string shownRoot;  // the folder read, as messages name it
    int entries = 0;
    std::size_t bytes = 0;
    const std::set<std::string>* shipped = nullptr;
    std::string setAside;  // a top-level name not copied (Submission::setAside)
    bool setAsideSeen = false;
    std::vector<std::string> files, notes, skipped;
};

std::string joinRel(const std::string& a, const std::string& b) {
    return a.empty() ? b : a + "/" + b;
}

// Copies the regular files under the folder `fd` (relative path `rel`) into `outFd`, opening
// each name once, never through a link.
void copyTree(Walk& w, int fd, const std::string& rel, int outFd, int depth) {
    std::string shown = printableName(joinRel(w.shownRoot, rel));
    if (depth > kMaxDepth)
        throw IntakeError(shown + ": folders nested more than " + std::to_string(kMaxDepth) +
                          " deep");
    for (const std::string& name : listFolder(fd, w.entries, shown)) {
        std::string path = joinRel(rel, name);
        if (rel.empty() && !w.setAside.empty() && name == w.setAside) {
            w.setAsideSeen = true;  // read apart, bounded: never a shader, never in the snapshot
            continue;
        }
        int f = ::openat(fd, name.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
        if (f < 0) {
            w.skipped.push_back("`" + printableName(path) + "` was not used: " +
                                (errno == ELOOP ? std::string("a symbolic link")
                                                : std::string(std::strerror(errno))));
            continue;
        }
        Fd in(f);
        struct stat st;
        if (::fstat(in.fd, &st) != 0) continue;
        if (S_ISDIR(st.st_mode)) {
            if (::mkdirat(outFd, name.c_str(), 0700) != 0)
                throw std::runtime_error("intake: cannot make a folder in the snapshot: " +
                                         std::string(std::strerror(errno)));
            Fd out(::openat(outFd, name.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC));
            if (out.fd < 0)
                throw std::runtime_error("intake: cannot open the snapshot's folder: " +
                                         std::string(std::strerror(errno)));
            copyTree(w, in.fd, path, out.fd, depth + 1);
            continue;
        }
        if (!S_ISREG(st.st_mode)) {
            w.skipped.push_back("`" + printableName(path) + "` was not used: not a regular file");
            continue;
        }
        const bool shipped = w.shipped->count(path) > 0;
        // A hard link is a second name of a file that may live anywhere (another student's
        // work, a secret): copied, it would lose that mark, so it is refused as the loader does.
        if (st.st_nlink > 1) {
            std::string why =
                std::to_string(st.st_nlink) +
                " hard links; a file in the shader folder must have one name (copy it)";
            if (shipped)
                throw IntakeError(printableName(joinRel(w.shownRoot, path)) + ": has " + why);
            w.skipped.push_back("`" + printableName(path) + "` was not used: it has " + why);
            continue;
        }
        if (static_cast<std::size_t>(st.st_size) > kMaxFileBytes) {
            if (shipped)
                throw IntakeError(
                    printableName(joinRel(w.shownRoot, path)) + ": " + std::to_string(st.st_size) +
                    " bytes; a shader file holds at most " + std::to_string(kMaxFileBytes));
            w.skipped.push_back("`" + printableName(path) + "` was not used: larger than 1 MiB");
            continue;
        }
        // Read once, bounded by the size limit whatever fstat said (a file may grow meanwhile).
        std::string text;
        char buffer[65536];
        for (;;) {
            ssize_t n = ::read(in.fd, buffer, sizeof buffer);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) break;
            text.append(buffer, static_cast<std::size_t>(n));
            if (text.size() > kMaxFileBytes)
                throw IntakeError(printableName(joinRel(w.shownRoot, path)) +
                                  ": grew past 1 MiB while it was read");
        }
        w.bytes += text.size();
        if (w.bytes > kMaxTotalBytes)
            throw IntakeError(printableName(w.shownRoot) + ": more than " +
                              std::to_string(kMaxTotalBytes >> 20) +
                              " MiB of files; a submission is a few shader files");
        Fd out(::openat(outFd, name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC,
                        0600));
        if (out.fd < 0) throw SnapshotWriteError(errno);
        std::size_t done = 0;
        while (done < text.size()) {
            ssize_t n = ::write(out.fd, text.data() + done, text.size() - done);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) throw SnapshotWriteError(n < 0 ? errno : ENOSPC);
            done += static_cast<std::size_t>(n);
        }
        w.files.push_back(path);
    }
}

std::string baseName(const std::string& path) {
    std::size_t slash = path.rfind('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string stageOf(const std::string& path) {
    std::size_t slash = path.find('/');
    return slash == std::string::npos ? "" : path.substr(0, slash);
}

// Spellings a student may have meant for `path`: itself, and with the extension a shipped file
// has (`.fs` -> `.frag`, `.vs` -> `.vert`, `.glsl`/`.txt` dropped or swapped).
std::vector<std::string> respellings(const std::string& path) {
    std::vector<std::string> out = {path};
    std::size_t dot = path.rfind('.');
    if (dot == std::string::npos || dot < path.rfind('/') + 1) return out;
    std::string stem = path.substr(0, dot), ext = lower(path.substr(dot));
    if (ext == ".fs" || ext == ".frag" || ext == ".fsh" || ext == ".glsl" || ext == ".txt")
        out.push_back(stem + ".frag");
    if (ext == ".vs" || ext == ".vert" || ext == ".vsh" || ext == ".glsl" || ext == ".txt")
        out.push_back(stem + ".vert");
    if (ext == ".txt" || ext == ".glsl") out.push_back(stem);  // lit.frag.txt, lit.frag.glsl
    if (ext == ".txt") out.push_back(stem + ".glsl");
    return out;
}

// The shipped files a student's `path` nearly names, or none: the same path in another case or
// spelling, under a copied shaders_core/ or shaders_legacy/ folder (one file), or for a file at
// the top, every graded stage's file of that name (lit.frag is several stages' file). With
// `stages` (those being graded), only their files are suggested, and with `listed` only the
// files an assignment grades: a hint towards a file nobody grades sends the student the wrong
// way.
std::vector<std::string> nearMisses(const std::string& path,
                                    const std::map<std::string, std::string>& byLower,
                                    const std::set<std::string>& shipped,
                                    const std::vector<std::string>& stages,
                                    const std::set<std::string>& listed) {
    auto graded = [&](const std::string& file) {
        return stages.empty() ||
               std::find(stages.begin(), stages.end(), stageOf(file)) != stages.end();
    };
    auto suggested = [&](const std::string& file) {
        return graded(file) && (listed.empty() || listed.count(file));
    };
    std::string p = path;
    for (const char* tree : {"shaders_core/", "shaders_legacy/"})
        if (lower(p).rfind(tree, 0) == 0) p = p.substr(std::strlen(tree));
    for (const std::string& r : respellings(p)) {
        auto it = byLower.find(lower(r));
        if (it != byLower.end())
            return graded(it->second) ? std::vector<std::string>{it->second}
                                      : std::vector<std::string>{};
    }
    if (p.find('/') != std::string::npos) return {};
    std::vector<std::string> named;  // in the order of `stages` (the assignment's)
    for (const std::string& r : respellings(p)) {
        for (const std::string& s : shipped)
            if (suggested(s) && lower(baseName(s)) == lower(r)) named.push_back(s);
        if (!named.empty()) break;
    }
    auto rank = [&](const std::string& f) {
        return std::find(stages.begin(), stages.end(), stageOf(f)) - stages.begin();
    };
    std::stable_sort(named.begin(), named.end(),
                     [&](const std::string& x, const std::string& y) { return rank(x) < rank(y); });
    return named;
}

// The note for `file` that was not used and nearly names `meant` (nearMisses): the files it
// may be that the hand-in lacks ("did you mean `bias/lit.frag`?"), or, for a file at the top
// when every one of them was handed in, where a stage's file goes. "" when it names nothing.
std::string nearMissNote(const std::string& file, const std::vector<std::string>& meant,
                         const std::set<std::string>& present) {
    constexpr std::size_t kMaxNamed = 3;
    std::vector<std::string> lacking;
    for (const std::string& m : meant)
        if (!present.count(m)) lacking.push_back(m);
    const bool atTop = file.find('/') == std::string::npos;
    const std::vector<std::string>& named = lacking.empty() && atTop ? meant : lacking;
    if (named.empty()) return "";
    const std::string last = lacking.empty() ? " and " : " or ";
    std::string list;
    for (std::size_t i = 0; i < named.size() && i < kMaxNamed; ++i)
        list += (i == 0                                       ? ""
                 : i + 1 == std::min(named.size(), kMaxNamed) ? last
                                                              : ", ") +
                "`" + named[i] + "`";
    if (named.size() > kMaxNamed) list += last + "another stage's";
    const std::string head = "`" + printableName(file) + "` was not used: ";
    if (!lacking.empty()) return head + "did you mean " + list + "?";
    return head + "a stage's files go in its folder, and " + list +
           (named.size() == 1 ? " is" : " are") + " handed in already";
}

}  // namespace

// Editor and archive leftovers: never a shader, never mentioned.
SnapshotWriteError::SnapshotWriteError(int err)
    : std::runtime_error(
          err == ENOSPC || err == EDQUOT
              ? "the grading machine's disk is full (" + std::string(std::strerror(err)) +
                    "): the hand-in could not be copied; not the submission's fault: free space "
                    "and grade again"
              : "the grading machine could not copy the hand-in (" +
                    std::string(std::strerror(err)) + "): not the submission's fault") {}

std::string junkReason(const std::string& name) {
    if (name.empty()) return "no name";
    const std::string low = lower(name);
    if (low == "__macosx" || low == "thumbs.db" || low == "desktop.ini" || low == ".ds_store" ||
        low.rfind("._", 0) == 0)
        return "operating-system leftovers";
    if (name[0] == '.') return "a hidden name";           // .lit.frag.swp, .git, .hidden
    if (name.back() == '~') return "an editor's backup";  // emacs, gedit
    if (name.size() > 1 && name[0] == '#' && name.back() == '#') return "an editor's autosave";
    for (const char* ext : {".swp", ".swo", ".bak", ".orig"})
        if (endsWith(low, ext)) return "an editor's backup";
    return "";
}

bool isJunkName(const std::string& name) {
    return !junkReason(name).empty();
}

std::set<std::string> shippedFiles(const std::string& treeRoot) {
    std::set<std::string> out;
    std::error_code ec;
    namespace fs = std::filesystem;
    for (fs::recursive_directory_iterator it(treeRoot, ec), end; !ec && it != end; it.increment(ec))
        if (it->is_regular_file(ec))
            out.insert(fs::relative(it->path(), treeRoot, ec).generic_string());
    return out;
}

const ShippedTrees& shippedTrees() {
    static const ShippedTrees trees = [] {
        ShippedTrees t;
        t.core = shippedFiles(shaderTreeRoot(GlslTree::Core));
        t.legacy = shippedFiles(shaderTreeRoot(GlslTree::Legacy));
        t.both = t.core;
        t.both.insert(t.legacy.begin(), t.legacy.end());
        return t;
    }();
    return trees;
}

Submission takeSubmission(const std::string& folder, const std::string& privateDir,
                          const std::set<std::string>& shipped,
                          const std::vector<std::string>& stages,
                          const std::set<std::string>& listed, const std::string& setAside) {
    Submission s;
    s.source = s.folder = folder;
    s.root = privateDir;
    if (folder.empty()) throw IntakeError("--shaders: give the student's folder");
    // The folder the instructor named may be a link; nothing inside it is followed.
    Fd top(::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
    if (top.fd < 0)
        throw IntakeError(printableName(folder) + ": " +
                          (errno == ENOTDIR ? "not a folder" : std::strerror(errno)));
    std::set<std::string> topNames;  // shipped top-level folders, in lower case
    for (const std::string& f : shipped) topNames.insert(lower(stageOf(f)));
    int entries = 0;
    int current = ::dup(top.fd);
    for (int level = 0; level < kMaxWrappers; ++level) {
        std::vector<std::string> names = listFolder(current, entries, printableName(s.folder));
        if (names.size() != 1 || topNames.count(lower(names[0]))) break;
        int inner =
            ::openat(current, names[0].c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
        if (inner < 0) break;  // a lone file or link: read as it is
        ::close(current);
        current = inner;
        // A lone copy of a shipped tree's folder is a wrapper too: it holds the stage folders.
        const bool tree = lower(names[0]) == "shaders_core" || lower(names[0]) == "shaders_legacy";
        s.notes.push_back("the submission is one folder, `" + printableName(names[0]) + "/`" +
                          (tree ? " (a copy of the shipped shader tree)" : "") +
                          ": graded what is inside it");
        s.folder = joinRel(s.folder, names[0]);
    }
    Fd reading(current);
    Fd out(::open(privateDir.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC));
    if (out.fd < 0)
        throw std::runtime_error("intake: cannot open the private folder " + privateDir + ": " +
                                 std::strerror(errno));
    Walk w;
    w.shownRoot = s.folder;
    w.shipped = &shipped;
    w.setAside = setAside;
    copyTree(w, reading.fd, "", out.fd, 0);
    if (w.setAsideSeen) {
        HandInFile f{setAside, "", ""};
        f.problem = readRegularFile(joinRel(s.folder, setAside), kMaxSetAsideBytes, f.text, true);
        s.setAside = std::move(f);
    }
    std::sort(w.files.begin(), w.files.end());
    s.files = w.files;

    std::map<std::string, std::string> byLower;
    for (const std::string& f : shipped) byLower.emplace(lower(f), f);
    std::set<std::string> present(s.files.begin(), s.files.end());
    std::vector<std::string> misses;
    bool replacesAny = false;
    for (const std::string& f : s.files) {
        if (shipped.count(f)) {
            replacesAny = true;
            continue;
        }
        std::string note =
            nearMissNote(f, nearMisses(f, byLower, shipped, stages, listed), present);
        if (!note.empty()) misses.push_back(note);
    }
    for (const auto* list : {&misses, &w.skipped})
        for (const std::string& n : *list) s.notes.push_back(n);
    if (s.notes.size() > kMaxNotes) {
        std::size_t more = s.notes.size() - kMaxNotes;
        s.notes.resize(kMaxNotes);
        s.notes.push_back("and " + std::to_string(more) + " more files not used");
    }
    if (!replacesAny) {
        // The graded stage's own file when it has one, else the first lit.frag in lecture order.
        std::string example;
        for (const std::string& id : stageIds())
            if (example.empty() && shipped.count(id + "/lit.frag")) example = id + "/lit.frag";
        for (const std::string& f : shipped)
            if (!stages.empty() && stageOf(f) == stages.front() &&
                (example.rfind(stages.front() + "/", 0) != 0 || baseName(f) == "lit.frag"))
                example = f;
        std::string line = printableName(s.source) +
                           ": no file replaces a shipped shader (a stage's files go in "
                           "<stage>/, e.g. " +
                           example + ")";
        if (!misses.empty()) line += "; " + misses.front();
        throw NothingHandedIn(line);
    }
    s.hash = contentHash(privateDir);
    return s;
}

std::vector<std::string> stageFiles(const Submission& s, const std::string& stage,
                                    const std::set<std::string>& shipped) {
    std::vector<std::string> out;
    for (const std::string& f : s.files)
        if (stageOf(f) == stage && shipped.count(f)) out.push_back(f);
    return out;
}

std::vector<std::string> expectedFiles(const std::string& stage,
                                       const std::set<std::string>& shipped) {
    std::vector<std::string> out;
    for (const std::string& f : shipped)
        if (stageOf(f) == stage) out.push_back(f);
    return out;
}

}  // namespace sl
