# The student corpus (tests/students/): submissions written for grading, each with the verdict an
# instructor decided from its shaders and pictures. Every case must get that verdict from `check`
# (every lesson and view of its stage); the runner prints the cases that disagree and their figures.
add_test(NAME student_corpus
         COMMAND python3 ${CMAKE_CURRENT_SOURCE_DIR}/students/run_students.py
                 --exe $<TARGET_FILE:shadowlab> --work ${CMAKE_BINARY_DIR}/students-ci --jobs 2)
set_tests_properties(student_corpus PROPERTIES LABELS "check;students" TIMEOUT 1800)

# The runner itself: worst-row reading of nested report rows, case.json validation (no GL).
add_test(NAME student_corpus_runner
         COMMAND python3 ${CMAKE_CURRENT_SOURCE_DIR}/students/test_run_students.py)
set_tests_properties(student_corpus_runner PROPERTIES LABELS "students")
