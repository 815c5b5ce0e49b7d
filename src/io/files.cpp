#include "io/files.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <vector>

namespace sl {

namespace {

std::string failure(const std::string& path, const std::string& why) {
    return "cannot write '" + path + "': " + why;
}

std::string kindOf(mode_t mode) {
    if (S_ISDIR(mode)) return "a folder";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
    if (S_ISSOCK(mode)) return "a socket";
    if (S_ISLNK(mode)) return "a symbolic link";
    return "not a regular file";
}

std::string folderOf(const std::string& path) {
    std::size_t slash = path.find_last_of('/');
    if (slash == std::string::npos) return ".";
    return slash == 0 ? "/" : path.substr(0, slash);
}

}  // namespace

std::string readRegularFile(const std::string& path, std::size_t maxBytes, std::string& text,
                            bool noFollow) {
    struct stat st;
    // stat first: opening a FIFO for reading would block until a writer comes.
    if ((noFollow ? ::lstat(path.c_str(), &st) : ::stat(path.c_str(), &st)) != 0)
        return std::strerror(errno);
    if (!S_ISREG(st.st_mode)) return "it is " + kindOf(st.st_mode) + ", not a regular file";
    // O_NONBLOCK: should the name have become a FIFO since the stat, open still returns at once.
    int flags = O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY | (noFollow ? O_NOFOLLOW : 0);
    int fd = ::open(path.c_str(), flags);
    if (fd < 0) return std::strerror(errno);
    std::string why;
    if (::fstat(fd, &st) != 0)
        why = std::strerror(errno);
    else if (!S_ISREG(st.st_mode))
        why = "it is " + kindOf(st.st_mode) + ", not a regular file";
    else if (std::size_t(st.st_size) > maxBytes)
        why = "it has " + std::to_string(st.st_size) + " bytes; at most " +
              std::to_string(maxBytes) + " are allowed";
    text.clear();
    // Read at most maxBytes + 1 whatever the size said: a file may grow while we read it.
    std::vector<char> buffer(64 * 1024);
    while (why.empty()) {
        ssize_t n = ::read(fd, buffer.data(), buffer.size());
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            why = std::strerror(errno);
        } else if (n == 0) {
            break;
        } else {
            text.append(buffer.data(), std::size_t(n));
            if (text.size() > maxBytes)
                why = "it has more than " + std::to_string(maxBytes) + " bytes";
        }
    }
    ::close(fd);
    if (!why.empty()) text.clear();
    return why;
}

std::string outputPathProblem(const std::string& path) {
    if (path.empty()) return failure(path, "no file name given");
    if (path.back() == '/') return failure(path, "it is a folder; give a file name");
    struct stat st;
    if (::lstat(path.c_str(), &st) == 0) {
        if (S_ISDIR(st.st_mode)) return failure(path, "it is a folder; give a file name");
        if (S_ISLNK(st.st_mode))
            return failure(path, "it is a symbolic link (refused: remove it or give another name)");
        // Renaming over a device would replace it (we may run as root).
        if (!S_ISREG(st.st_mode)) return failure(path, "it is not a regular file (a device?)");
        // Mode bits, not only access(): root may write anything, but a read-only file is a
        // request not to replace it.
        if ((st.st_mode & S_IWUSR) == 0 || ::access(path.c_str(), W_OK) != 0)
            return failure(path, "it is read-only (refused: make it writable or remove it)");
        return {};
    }
    if (errno != ENOENT) return failure(path, std::strerror(errno));
    std::string folder = folderOf(path);
    if (::stat(folder.c_str(), &st) != 0)
        return failure(path, errno == ENOENT ? "the folder '" + folder + "' does not exist"
                                             : std::strerror(errno));
    if (!S_ISDIR(st.st_mode)) return failure(path, "'" + folder + "' is not a folder");
    return {};
}

namespace {

// Writes all `size` bytes to `fd`; 0 or the errno of the failed write.
int writeAll(int fd, const char* p, std::size_t size) {
    while (size > 0) {
        ssize_t n = ::write(fd, p, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return n < 0 ? errno : ENOSPC;
        p += n;
        size -= std::size_t(n);
    }
    return 0;
}

// A temporary name beside `path` that no one can guess ahead: path.tmpPID-COUNT-NANOSECONDS.
std::string temporaryName(const std::string& path) {
    static unsigned counter = 0;
    struct timespec now;
    ::clock_gettime(CLOCK_MONOTONIC, &now);
    char suffix[64];
    std::snprintf(suffix, sizeof suffix, ".tmp%d-%u-%ld", int(::getpid()), counter++,
                  long(now.tv_nsec));
    return path + suffix;
}

// The data in an unnamed file in the target's folder (O_TMPFILE), then given a temporary name
// with linkat (which never replaces an existing name nor follows a link planted there) and
// renamed over `path`: a process killed while writing (a worker at its time limit) leaves
// nothing behind. -1: the file system or a missing /proc cannot; the caller falls back.
int writeUnnamed(const std::string& path, const void* data, std::size_t size, mode_t mode) {
#ifdef __EMSCRIPTEN__
    return -1;  // the browser's memory file system links /proc/self/fd/N as a dangling symlink
#endif
    int fd = ::open(folderOf(path).c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, mode);
    if (fd < 0) return -1;
    int error = writeAll(fd, static_cast<const char*>(data), size);
    std::string source = "/proc/self/fd/" + std::to_string(fd), tmp;
    for (int attempt = 0; !error && tmp.empty() && attempt < 100; ++attempt) {
        std::string name = temporaryName(path);
        if (::linkat(AT_FDCWD, source.c_str(), AT_FDCWD, name.c_str(), AT_SYMLINK_FOLLOW) == 0)
            tmp = name;
        else if (errno != EEXIST) {
            ::close(fd);
            return -1;
        }
    }
    if (::close(fd) != 0 && !error) error = errno;
    if (!error && tmp.empty()) error = EEXIST;
    if (!error && std::rename(tmp.c_str(), path.c_str()) != 0) error = errno;
    if (error && !tmp.empty()) ::unlink(tmp.c_str());
    return error;
}

}  // namespace

namespace {

// The error's text, with errno left at `error` for the caller (diskFull(errno)).
std::string failed(const std::string& path, int error) {
    std::string text = failure(path, std::strerror(error));
    errno = error;
    return text;
}

}  // namespace

std::string writeFileAtomically(const std::string& path, const void* data, std::size_t size) {
    if (std::string err = outputPathProblem(path); !err.empty()) return err;
#ifdef __EMSCRIPTEN__
    const mode_t mask = 022;  // emscripten's umask() gives 0777: files nobody could read back
#else
    const mode_t mask = ::umask(0);
    ::umask(mask);
#endif
    int error = writeUnnamed(path, data, size, 0666 & ~mask);
    if (error > 0) return failed(path, error);
    if (error == 0) return {};
    // No O_TMPFILE here: mkstemp creates the name with O_EXCL, so a planted file or symlink at
    // a guessed temporary name makes it pick another, never write through it.
    std::string tmp = path + ".tmpXXXXXX";
    int fd = ::mkostemp(tmp.data(), O_CLOEXEC);
    if (fd < 0) return failed(path, errno);
    ::fchmod(fd, 0666 & ~mask);  // mkstemp's 0600 would make outputs unreadable to others
    error = writeAll(fd, static_cast<const char*>(data), size);
    if (::close(fd) != 0 && !error) error = errno;
    if (!error && std::rename(tmp.c_str(), path.c_str()) != 0) error = errno;
    if (error) {
        ::unlink(tmp.c_str());
        return failed(path, error);
    }
    return {};
}

bool diskFull(int error) {
    return error == ENOSPC || error == EDQUOT;
}

std::string writeTextFile(const std::string& path, const std::string& text) {
    return writeFileAtomically(path, text.data(), text.size());
}

std::string printable(const std::string& text) {
    std::string out = text;
    for (char& c : out) {
        unsigned char u = static_cast<unsigned char>(c);
        if ((u < 0x20 && c != '\n' && c != '\t') || u == 0x7f) c = '?';
    }
    return out;
}

namespace {

// `text` with each byte that is not part of valid UTF-8 replaced by `bad(byte)`.
template <class Bad>
std::string keptUtf8(const std::string& text, Bad bad) {
    std::string out;
    out.reserve(text.size());
    std::size_t i = 0, n = text.size();
    while (i < n) {
        unsigned char c = static_cast<unsigned char>(text[i]);
        std::size_t length = c < 0x80           ? 1
                             : (c >> 5) == 0x6  ? 2
                             : (c >> 4) == 0xe  ? 3
                             : (c >> 3) == 0x1e ? 4
                                                : 0;
        bool ok = length > 0 && i + length <= n && !(c == 0xc0 || c == 0xc1 || c > 0xf4);
        for (std::size_t k = 1; ok && k < length; ++k)
            ok = (static_cast<unsigned char>(text[i + k]) & 0xc0) == 0x80;
        if (ok && length == 3) {  // no overlong forms, no surrogates
            unsigned char d = static_cast<unsigned char>(text[i + 1]);
            ok = !(c == 0xe0 && d < 0xa0) && !(c == 0xed && d >= 0xa0);
        }
        if (ok && length == 4) {
            unsigned char d = static_cast<unsigned char>(text[i + 1]);
            ok = !(c == 0xf0 && d < 0x90) && !(c == 0xf4 && d >= 0x90);
        }
        if (ok) {
            out.append(text, i, length);
            i += length;
        } else {
            out += bad(static_cast<unsigned char>(text[i]));
            ++i;
        }
    }
    return out;
}

std::string hexByte(unsigned char c) {
    char t[8];
    std::snprintf(t, sizeof t, "\\x%02X", c);
    return t;
}

}  // namespace

std::string validUtf8(const std::string& text) {
    return keptUtf8(text, [](unsigned char) { return std::string("?"); });
}

std::string escapedName(const std::string& name) {
    return keptUtf8(name, hexByte);
}

const std::string* handInNamed(const std::vector<std::string>& names, const std::string& given) {
    for (const std::string& n : names)
        if (n == given) return &n;
    for (const std::string& n : names)
        if (escapedName(n) != n && escapedName(n) == given) return &n;
    return nullptr;
}

namespace {
std::string& copyFolder() {
    static std::string folder;
    return folder;
}
std::string& originalFolder() {
    static std::string folder;
    return folder;
}
}  // namespace

void showFolderAs(const std::string& copy, const std::string& original) {
    copyFolder() = copy;
    originalFolder() = original;
}

std::string withShownFolders(const std::string& text) {
    const std::string& from = copyFolder();
    if (from.empty() || text.find(from) == std::string::npos) return text;
    std::string out;
    std::size_t at = 0;
    for (std::size_t hit; (hit = text.find(from, at)) != std::string::npos;
         at = hit + from.size()) {
        out.append(text, at, hit - at);
        out += originalFolder();
    }
    return out + text.substr(at);
}

std::string printableName(const std::string& name) {
    std::string out = validUtf8(withShownFolders(name));
    for (char& c : out) {
        unsigned char u = static_cast<unsigned char>(c);
        if (u < 0x20 || u == 0x7f) c = '?';
    }
    return out;
}

std::string capped(const std::string& text, std::size_t maxBytes) {
    if (text.size() <= maxBytes) return text;
    std::size_t keep = maxBytes;
    // Back up over continuation bytes (10xxxxxx) so the cut falls between characters.
    while (keep > 0 && (static_cast<unsigned char>(text[keep]) & 0xC0) == 0x80) --keep;
    return text.substr(0, keep) + " [... " + std::to_string(text.size() - keep) + " bytes cut]";
}

namespace {

bool inside(const std::filesystem::path& child, const std::filesystem::path& parent) {
    auto c = child.begin(), p = parent.begin();
    for (; p != parent.end(); ++p, ++c)
        if (c == child.end() || *c != *p) return false;
    return true;
}

std::filesystem::path resolved(const std::string& path) {
    std::error_code ec;
    std::filesystem::path p =
        std::filesystem::weakly_canonical(std::filesystem::absolute(path, ec), ec);
    return ec ? std::filesystem::absolute(path).lexically_normal() : p;
}

}  // namespace

bool liesWithin(const std::string& path, const std::string& folder) {
    return inside(resolved(path), resolved(folder));
}

}  // namespace sl
