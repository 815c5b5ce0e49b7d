// Students graded in one series of bounded workers: every student's handed-in stages in one
// plan, so the worker's evaluator (and its references, traced once per view) serves the whole
// series; a stage that kills its worker costs that stage only. Used by `check --assignment`
// (one student) and `grade` (a share of the class per job).
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "course/student_grade.h"
#include "platform/headless.h"

namespace sl {

struct GradeSettings {
    Backend backend = Backend::Auto;
    Limits limits;
    bool pictures = false;  // write render, truth and diff images per row
    // The displaced views' seed (check_run.h: drawn once per run, so a class shares one view
    // and its reference is traced once); none: no displaced view.
    std::optional<std::uint64_t> seed;
    // The folder of a student's images ("" = no images).
    std::function<std::string(const StudentWork&)> imageDir;
};

// Grades `students` in order; `done(k, record)` as each one's last stage comes back (a student
// with nothing to render at once). Returns true when a GL or platform failure happened (exit 3).
bool gradeStudents(const Assignment& a, const std::vector<StudentWork>& students,
                   const GradeSettings& settings,
                   const std::function<void(std::size_t, const nlohmann::json&)>& done);

// The file name of a row's images: "STAGE-TREE-VIEW-LESSON" with only [A-Za-z0-9._-].
std::string rowSlug(const CheckCase& c);

}  // namespace sl
