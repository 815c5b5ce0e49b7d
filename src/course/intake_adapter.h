// The one door from the course code to a submission's intake. Issue 19's intake (grade/intake.h
// on branch h19a: takeSubmission, stageFiles, PrivateDir) was not published when this was
// written; this adapter does what the course needs in the same spirit and is the only place to
// switch at merge: unpack a zip here (course/archive.h), then call takeSubmission(folder,
// workDir + "/snapshot", shippedFiles of both trees, the due stages) and fill a StudentWork
// from its Submission (root -> overlay, files, notes); its IntakeError for a hand-in that
// replaces no shipped file should become a StudentWork with no files (every due stage MISSING),
// not an error. (StudentWork, not Submission: that name is intake.h's.)
#pragma once

#include <string>
#include <vector>

namespace sl {

struct StudentWork {
    std::string name;                // the student: folder name or zip stem
    std::string overlay;             // the private snapshot to grade ("" when refused)
    std::vector<std::string> files;  // relative paths of the student's regular files in it
    std::vector<std::string> notes;  // wrapper folders descended, junk and links skipped, ...
    std::string error;               // why the submission could not be read at all ("" = ok)
    bool has(const std::string& rel) const;
};

// Reads the folder or .zip at `path` into a snapshot under `workDir` (created; emptied first):
// a zip is unpacked safely (course/archive.h); a lone wrapper folder is descended, a lone zip
// inside is unpacked; junk (__MACOSX/, .DS_Store, editor backups) skipped; only regular files
// are copied (links skipped with a note), within the same bounds as a zip.
StudentWork intakeSubmission(const std::string& path, const std::string& workDir);

// The student's name for an entry of a class folder: its base name, without ".zip".
std::string submissionName(const std::string& path);

}  // namespace sl
