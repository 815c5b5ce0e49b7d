// The student's folder the page last picked (web_main.cpp), as the page copied it: what the
// page's check (web_check.cpp) takes again and grades, as `check --shaders` takes and grades the
// folder it is given, whether or not the page could draw it.
#pragma once

#include <string>

namespace sl::web {

struct PickedFolder {
    std::string path;  // the page's copy ("" = our shaders)
    std::string name;  // the folder as the student picked it
};
PickedFolder pickedFolder();

// The folder the intake read (`read`: the picked one's copy or a folder in it): its path inside
// the copy ("" for the copy itself), and its name as the student picked it ("lab4/inner").
std::string insidePicked(const PickedFolder& picked, const std::string& read);
std::string shownAsPicked(const PickedFolder& picked, const std::string& read);

// `text` with the copy's path named as the student picked it.
std::string asPicked(const std::string& text);

// Messages name the files of the snapshot on screen again (io/files.h showFolderAs: one folder
// at a time), after the check named its own.
void nameDrawnFolder();

}  // namespace sl::web
