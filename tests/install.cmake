# `cmake --install` into a temporary prefix, moved elsewhere, grades a submission without the
# source tree (tests/install/grade_installed.sh).
add_test(NAME install_and_grade
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/install/grade_installed.sh ${CMAKE_BINARY_DIR}
                 ${CMAKE_SOURCE_DIR})
set_tests_properties(install_and_grade PROPERTIES LABELS command TIMEOUT 300)
# The student edition: the default install holds no solution line; the `solutions` component
# brings the marked trees back for the instructor (tests/install/student_edition.sh).
add_test(NAME install_student_edition
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/install/student_edition.sh ${CMAKE_BINARY_DIR}
                 ${CMAKE_SOURCE_DIR})
set_tests_properties(install_student_edition PROPERTIES LABELS command TIMEOUT 900)
# `release --gradescope`'s zip holds exactly the files the build read (source_kit.txt) and its
# sources configure and preprocess alone (tests/install/autograder_zip.sh; CI builds it whole:
# scripts/gradescope_suite.sh).
add_test(NAME install_autograder_zip
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/install/autograder_zip.sh ${CMAKE_BINARY_DIR}
                 ${CMAKE_SOURCE_DIR})
set_tests_properties(install_autograder_zip PROPERTIES LABELS command TIMEOUT 600)
