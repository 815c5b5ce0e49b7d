#include "course/archive.h"

#include <archive.h>
#include <archive_entry.h>
#include <fcntl.h>
#include <limits.h>
#include <locale.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <memory>
#include <vector>

#include "grade/intake.h"
#include "io/files.h"

namespace sl {

namespace {

// "" when `name` is a relative path of plain parts; else why not.
std::string pathProblem(const std::string& name) {
    if (name.empty()) return "an entry without a name";
    // ':' is an ordinary character here ("Screen Shot 10:30.png"); '\\' would be a folder on
    // the student's Windows, so it is not taken as part of a name.
    if (name[0] == '/' || name.find('\\') != std::string::npos)
        return "'" + printableName(name) + "' is not a plain relative path";
    std::size_t start = 0;
    while (start <= name.size()) {
        std::size_t end = name.find('/', start);
        if (end == std::string::npos) end = name.size();
        std::string part = name.substr(start, end - start);
        if (part == "..") return "'" + printableName(name) + "' leaves the folder ('..')";
        if (part.empty() && end != name.size())
            return "'" + printableName(name) + "' has an empty part";
        start = end + 1;
    }
    return "";
}

// Creates every folder of `rel` under `root` (no link followed: each part must be a folder we
// made or one that is a real folder).
bool makeParents(const std::string& root, const std::string& rel) {
    std::size_t slash = 0;
    while ((slash = rel.find('/', slash)) != std::string::npos) {
        std::string dir = root + "/" + rel.substr(0, slash);
        struct stat st;
        if (::lstat(dir.c_str(), &st) == 0) {
            if (!S_ISDIR(st.st_mode)) return false;
        } else if (::mkdir(dir.c_str(), 0700) != 0) {
            return false;
        }
        ++slash;
    }
    return true;
}

// The longest part of `name` exceeds what a file name may hold (NAME_MAX bytes).
bool partTooLong(const std::string& name) {
    std::size_t start = 0;
    while (start <= name.size()) {
        std::size_t end = name.find('/', start);
        if (end == std::string::npos) end = name.size();
        if (end - start > NAME_MAX) return true;
        start = end + 1;
    }
    return false;
}

// While alive, this thread reads names as UTF-8 (libarchive converts through the thread's
// locale: under the C locale a non-ASCII name cannot be converted and comes back empty).
class Utf8Names {
  public:
    Utf8Names() {
        utf8_ = ::newlocale(LC_CTYPE_MASK, "C.UTF-8", nullptr);
        if (utf8_) previous_ = ::uselocale(utf8_);
    }
    ~Utf8Names() {
        if (!utf8_) return;
        ::uselocale(previous_);
        ::freelocale(utf8_);
    }
    Utf8Names(const Utf8Names&) = delete;
    Utf8Names& operator=(const Utf8Names&) = delete;

  private:
    locale_t utf8_ = nullptr, previous_ = nullptr;
};

// The entry's name as UTF-8 (the zip's UTF-8 flag, else as stored), or its bytes as stored.
std::string entryName(archive_entry* entry) {
    if (const char* utf8 = archive_entry_pathname_utf8(entry)) return utf8;
    const char* raw = archive_entry_pathname(entry);
    return raw ? raw : "";
}

// A write that failed for want of space is the machine's fault, never the archive's.
void throwIfMachine(int err) {
    if (err == ENOSPC || err == EDQUOT || err == EIO) throw SnapshotWriteError(err);
}

}  // namespace

std::string unpackZip(const std::string& zip, const std::string& target, const UnpackLimits& limits,
                      std::vector<std::string>* notes) {
    const Utf8Names utf8Names;
    std::size_t leftOut = 0;
    struct stat st;
    if (::stat(zip.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return "not a regular file";
    if (std::size_t(st.st_size) > limits.maxArchiveBytes)
        return "the archive is larger than " + std::to_string(limits.maxArchiveBytes >> 20) + " MB";
    if (::mkdir(target.c_str(), 0700) != 0) {
        throwIfMachine(errno);
        return "cannot create the folder to unpack into";
    }
    std::unique_ptr<archive, int (*)(archive*)> a(archive_read_new(), archive_read_free);
    archive_read_support_format_zip(a.get());
    if (archive_read_open_filename(a.get(), zip.c_str(), 64 * 1024) != ARCHIVE_OK)
        return std::string("not a zip archive (") + archive_error_string(a.get()) + ")";
    std::size_t entries = 0, total = 0;
    std::vector<char> buffer(64 * 1024);
    archive_entry* entry = nullptr;
    for (;;) {
        int status = archive_read_next_header(a.get(), &entry);
        if (status == ARCHIVE_EOF) break;
        if (archive_read_has_encrypted_entries(a.get()) > 0 && status != ARCHIVE_OK &&
            status != ARCHIVE_WARN)
            return "the archive is encrypted: hand it in without a password";
        if (status != ARCHIVE_OK && status != ARCHIVE_WARN)
            return std::string("a damaged archive (") + archive_error_string(a.get()) + ")";
        if (++entries > limits.maxEntries)
            return "more than " + std::to_string(limits.maxEntries) + " entries";
        std::string name = entryName(entry);
        while (name.size() > 1 && name.back() == '/') name.pop_back();
        while (name.rfind("./", 0) == 0) name = name.substr(2);
        std::string problem = pathProblem(name);
        if (!problem.empty()) return problem;
        if (archive_entry_is_encrypted(entry))
            return "'" + printableName(name) + "' is encrypted: hand it in without a password";
        if (partTooLong(name)) {  // never a shipped file's name: left out, said once per entry
            if (notes && ++leftOut <= 5)
                notes->push_back("'" + printableName(name.substr(0, 60)) +
                                 "...' left out: its name is too long for a file name");
            continue;
        }
        if (archive_entry_hardlink(entry) || archive_entry_symlink(entry))
            return "'" + printableName(name) + "' is a link (links are not accepted)";
        mode_t type = archive_entry_filetype(entry);
        if (type == AE_IFDIR) {
            if (!makeParents(target, name + "/")) {
                throwIfMachine(errno);
                return "'" + printableName(name) + "': cannot create it";
            }
            continue;
        }
        if (type != AE_IFREG)
            return "'" + printableName(name) + "' is not a regular file or folder";
        if (!makeParents(target, name)) {
            throwIfMachine(errno);
            return "'" + printableName(name) + "': cannot create its folder";
        }
        std::string path = target + "/" + name;
        int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
        if (fd < 0) {
            throwIfMachine(errno);
            return "'" + printableName(name) + "' is there twice or cannot be written";
        }
        const std::string base = name.substr(name.rfind('/') + 1);
        const bool aside = !limits.asideName.empty() && base == limits.asideName;
        const std::size_t cap = aside ? limits.asideBytes : limits.maxFileBytes;
        std::size_t fileBytes = 0;
        std::string err;
        for (;;) {
            la_ssize_t n = archive_read_data(a.get(), buffer.data(), buffer.size());
            if (n == 0) break;
            if (n < 0) {
                err = std::string("a damaged archive (") + archive_error_string(a.get()) + ")";
                break;
            }
            fileBytes += std::size_t(n);
            total += std::size_t(n);
            if (fileBytes > cap) {
                err = "'" + printableName(name) + "' unpacks to more than " +
                      std::to_string(cap >> 10) + " KB";
                break;
            }
            if (total > limits.maxTotalBytes) {
                err = "the archive unpacks to more than " +
                      std::to_string(limits.maxTotalBytes >> 20) + " MB (a zip bomb?)";
                break;
            }
            if (ssize_t wrote = ::write(fd, buffer.data(), std::size_t(n)); wrote != n) {
                int why = wrote < 0 ? errno : ENOSPC;  // a short write: the disk is full
                ::close(fd);
                throwIfMachine(why);
                err = "cannot write '" + printableName(name) + "'";
                fd = -1;
                break;
            }
        }
        if (fd >= 0) ::close(fd);
        if (aside && fileBytes > cap) {  // never graded: left out, the hand-in is still taken
            ::unlink(path.c_str());
            if (notes) notes->push_back(err + ": left out");
            continue;
        }
        if (!err.empty()) return err;
    }
    if (notes && leftOut > 5)
        notes->push_back(std::to_string(leftOut - 5) + " more entries left out: names too long");
    return "";
}

}  // namespace sl
