// Intake: what a student handed in, resolved into the overlay it replaces and copied into a
// private folder before anything is compiled (GUIDE section 7). A lone wrapper folder (as a zip
// unpacks: `jdoe_lab4/margin/lit.frag`, a lone copy of `shaders_core/`) is descended into;
// editor and archive junk is left out; files that nearly match a shipped one (case, `.fs`, at
// the top, a copied `shaders_core/` path beside other entries) are named in a note and not used.
// Only regular files with one name are copied (no links, no hard links), within the loader's size
// limit and a count, each opened once without following links: the snapshot is what gets graded, so
// a student who edits or swaps files meanwhile changes nothing.
#pragma once

#include <cstddef>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "gl/shader_library.h"
#include "grade/plan.h"
#include "sandbox/private_dir.h"

namespace sl {

// The submission itself is unusable (not a folder, nothing in it replaces a shipped file, too
// many or too large files): exit 2, what() is the one line to print.
class IntakeError : public std::runtime_error {
  public:
    explicit IntakeError(const std::string& message) : std::runtime_error(message) {}
};

// The grading machine could not write the private copy (a full disk, a quota): never the
// student's fault; what() says so, and a full disk as such.
class SnapshotWriteError : public std::runtime_error {
  public:
    explicit SnapshotWriteError(int err);
};

// The submission was read, but no file in it replaces a shipped one (empty, a README, only near
// misses): for `check` exit 2; for an assignment every due stage is MISSING.
class NothingHandedIn : public IntakeError {
  public:
    using IntakeError::IntakeError;
};

// The bounds of one submission (the loader reads no shader file above 1 MiB): a handful of
// shaders fits easily; a hostile one (a million files, a disc image) costs a moment. The browser
// edition copies no more than these into its memory before the intake sees them.
struct IntakeLimits {
    std::size_t fileBytes, totalBytes;
    int entries;  // directory entries looked at, junk included
};
constexpr IntakeLimits kIntakeLimits{1u << 20, 16u << 20, 2048};

struct Submission {
    std::string source;              // the folder as given
    std::string folder;              // the folder read: source, or the wrapper descended into
    std::string root;                // the private snapshot: the overlay to grade
    std::vector<std::string> files;  // every file copied, relative to root, sorted
    std::vector<std::string> notes;  // one line each: wrapper, near misses, links skipped
    std::string hash;                // io/content_hash.h of the snapshot: what is graded
    // The file named `setAside` at the top of `folder`, when there: never in `files` or `root`.
    std::optional<HandInFile> setAside;
};

// The most a set-aside file (a student's own check report) may hold: `check --all`'s report of
// every stage in both trees is 1.1 MB.
constexpr std::size_t kMaxSetAsideBytes = 4u << 20;

// Editor and archive leftovers (`__MACOSX`, `.DS_Store` and other hidden names, `*~`, `#x#`,
// `.swp`, `.bak`...): never a shader, never mentioned.
// The one junk list, inside a submission and at the class level alike.
bool isJunkName(const std::string& name);

// Why `name` is junk, in a few words ("a hidden name", "an editor's backup", "operating-system
// leftovers"), or "" when it is not: what the class page and grade's summary say of an entry
// left out.
std::string junkReason(const std::string& name);

// The relative paths of every shipped file under `treeRoot` (e.g. "margin/lit.frag").
std::set<std::string> shippedFiles(const std::string& treeRoot);

// The shipped shader trees' files: each tree's, and both together (what a submission may
// replace). Read once per process (a class's students share them; they do not change meanwhile).
struct ShippedTrees {
    std::set<std::string> core, legacy, both;
    const std::set<std::string>& of(GlslTree tree) const {
        return tree == GlslTree::Core ? core : legacy;
    }
};
const ShippedTrees& shippedTrees();

// Resolves `folder` and copies its files into `privateDir` (an existing, empty folder of ours).
// `shipped`: the shipped files of every tree (a near miss is judged against them); `stages`: the
// stages being graded, the only ones a near miss suggests when given ("did you mean
// `margin/lit.frag`?"); `listed`, when not empty: the files an assignment grades, the only ones
// a top-level file's note suggests (mirror/lit.frag is mirror's, but an assignment may grade
// only mirror/surface.frag); `setAside`, when not empty: a file name at the top of the folder
// read (below its wrappers) that is never a shader: not copied, not listed, read into
// Submission::setAside within kMaxSetAsideBytes. Throws IntakeError when nothing replaces a
// shipped file.
Submission takeSubmission(const std::string& folder, const std::string& privateDir,
                          const std::set<std::string>& shipped,
                          const std::vector<std::string>& stages = {},
                          const std::set<std::string>& listed = {},
                          const std::string& setAside = "");

// The stage's own files (`<stage>/...`) that came from the student and replace one of
// `shipped` (one tree's files): none means the stage is MISSING.
std::vector<std::string> stageFiles(const Submission& s, const std::string& stage,
                                    const std::set<std::string>& shipped);

// The shipped files of `stage` in `shipped` (what a MISSING stage expected).
std::vector<std::string> expectedFiles(const std::string& stage,
                                       const std::set<std::string>& shipped);

}  // namespace sl
