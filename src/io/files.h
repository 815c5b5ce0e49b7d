// Files from untrusted places, read with bounds, and output files written without surprises.
// A student's folder or a scene file may be a FIFO, a device, a symlink to one, or huge: reads
// here never block, never run to the end of a device and never take more than a given size.
// Outputs are written to an exclusively created temporary file beside the target and renamed
// over it; an existing symlink, folder, device or read-only file is refused, never written
// through or replaced.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace sl {

// Reads the regular file `path` whole into `text` when it holds at most `maxBytes`. A FIFO, a
// device, a folder or a larger file is an error; with `noFollow` a symlink as the last
// component is one too. Returns "" or why it could not (without the path).
std::string readRegularFile(const std::string& path, std::size_t maxBytes, std::string& text,
                            bool noFollow = false);

// Why `path` cannot be written as an output file, as "cannot write 'PATH': why", or "" when it
// can: its folder must exist, and an existing `path` must be a writable regular file (not a
// symlink, folder, device or read-only file).
std::string outputPathProblem(const std::string& path);

// Writes `size` bytes atomically: into an unnamed file in `path`'s folder (O_TMPFILE, so a
// process killed meanwhile leaves nothing), linked to a fresh temporary name and renamed over
// `path`; where O_TMPFILE is not offered, into a temporary file created exclusively beside it
// (mkstemp). Never through an existing name or link; every write and close checked; on failure
// nothing is left. Returns "" or the error.
std::string writeFileAtomically(const std::string& path, const void* data, std::size_t size);
// (On failure errno is the cause: diskFull(errno) tells a full disk from a refused path.)

// ENOSPC or EDQUOT: the machine's disk or quota is full, never the input's fault.
bool diskFull(int error);

// A write that failed for want of space: the machine's failure (exit 3), said in one line that
// names the file; what was written before stays whole (every output is written atomically).
class DiskFullError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// Writes text atomically, as writeFileAtomically does.
std::string writeTextFile(const std::string& path, const std::string& text);

// The longest error text shown whole: a shader's log on stderr, a worker's error for its parent.
constexpr std::size_t kMaxErrorText = 16384;

// `text` whole when it holds at most `maxBytes`, else its first bytes (never splitting a UTF-8
// character) and " [... N bytes cut]".
std::string capped(const std::string& text, std::size_t maxBytes);

// `text` with control characters (other than newline and tab) replaced by '?': for terminal
// output of anything that came from a file (compiler logs, file names).
std::string printable(const std::string& text);

// `text` with every byte that is not part of valid UTF-8 replaced by '?'.
std::string validUtf8(const std::string& text);

// A name as the file system gave it, any bytes, in text that says which: valid UTF-8 kept,
// every other byte as \xNN ("caf\xE9" for Latin-1 "café"), so two names that differ in one
// byte are told apart on a page or in a gradebook (which then treat it as any text).
std::string escapedName(const std::string& name);

// The name of `names` that `given` names, `given` as an instructor types it (--regrade, a hand-in
// column of --times, --adjust or a roster, all UTF-8): the same bytes, else a name that is not
// UTF-8 whose escaped form, as every output shows it, is `given` ("caf\xE9"); nullptr if none.
const std::string* handInNamed(const std::vector<std::string>& names, const std::string& given);

// A file name as a message shows it: valid UTF-8, every control character (newline and tab
// included) as '?', so that a name from a student's folder keeps a message on one line.
std::string printableName(const std::string& name);

// Messages name files of a private copy (a graded submission's snapshot) by the folder they were
// copied from: after showFolderAs(copy, original), printableName and withShownFolders write
// `original` wherever a path starts with or a text holds `copy/`. One pair per process ("" clears).
void showFolderAs(const std::string& copy, const std::string& original);
std::string withShownFolders(const std::string& text);

// Whether `path` is `folder` or lies inside it, both resolved (links, `..`; a part not yet made
// is taken as spelled).
bool liesWithin(const std::string& path, const std::string& folder);

}  // namespace sl
