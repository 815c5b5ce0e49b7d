// A student's .zip unpacked safely (libarchive): regular files and folders only (a link, device
// or FIFO refuses the archive), no path outside the target (absolute, "..", empty parts), at
// most kMaxEntries entries, kMaxFileBytes per file and kMaxTotalBytes in all, counted on the
// bytes actually inflated so a zip bomb stops at the bound whatever its headers claim.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace sl {

struct UnpackLimits {
    std::size_t maxEntries = 1000;
    std::size_t maxFileBytes = 1u << 20;    // a shader is read up to 1 MB anyway
    std::size_t maxTotalBytes = 16u << 20;  // the whole submission
    std::size_t maxArchiveBytes = 16u << 20;
    // Entries of this base name (a student's own check report, which the intake sets aside) may
    // hold up to `asideBytes`; a larger one is left out with a note, never refusing the archive.
    std::string asideName;
    std::size_t asideBytes = 0;
};

// Unpacks `zip` into the folder `target` (created; must not exist). Returns "" or why the
// archive was refused (one line, naming the entry); on refusal `target` may hold a part. Names
// are read as UTF-8 whatever the process's locale; an entry whose name no file system can hold
// (a part longer than NAME_MAX) is left out with a line in `notes` (never a shipped file's
// name); an encrypted entry refuses the archive, saying so. Throws SnapshotWriteError
// (grade/intake.h) when the disk is full: the machine's fault, not the archive's.
std::string unpackZip(const std::string& zip, const std::string& target,
                      const UnpackLimits& limits = {}, std::vector<std::string>* notes = nullptr);

}  // namespace sl
