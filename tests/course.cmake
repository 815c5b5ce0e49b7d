# The course cycle (issue 20, docs/assignment.md) through the real binary: assignment errors,
# hostile zips, the release in both trees (no solution in it, starter fails, solution passes, the
# window runs on it), a class graded and its pages loaded in headless Chromium, and Gradescope's
# run_autograder in a simulated /autograder tree.
set(SL_COURSE_DIR ${CMAKE_BINARY_DIR}/course-ci)
set(SL_COURSE_PY ${CMAKE_CURRENT_SOURCE_DIR}/course)
file(MAKE_DIRECTORY ${SL_COURSE_DIR})
add_test(NAME course_assignment_errors
         COMMAND python3 ${SL_COURSE_PY}/test_assignment_errors.py $<TARGET_FILE:shadowlab> ${SL_COURSE_DIR}/errors)
add_test(NAME course_zip_safety
         COMMAND python3 ${SL_COURSE_PY}/test_zip_safety.py $<TARGET_FILE:shadowlab> ${CMAKE_SOURCE_DIR} ${SL_COURSE_DIR}/zips)
foreach(tree core legacy)
  add_test(NAME course_release_${tree}
           COMMAND python3 ${SL_COURSE_PY}/test_release.py $<TARGET_FILE:shadowlab> ${CMAKE_SOURCE_DIR} ${SL_COURSE_DIR}/release-${tree} ${tree})
  # Every stage released on its own: starter 0, solution full marks (long: a label of its own).
  add_test(NAME course_stages_${tree}
           COMMAND python3 ${SL_COURSE_PY}/test_stages_assignable.py $<TARGET_FILE:shadowlab> ${CMAKE_SOURCE_DIR} ${SL_COURSE_DIR}/stages-${tree} ${tree})
  set_tests_properties(course_stages_${tree} PROPERTIES LABELS "course;long" TIMEOUT 3600)
endforeach()
find_program(SL_CHROMIUM chromium)
if(SL_CHROMIUM)
  add_test(NAME course_grade
           COMMAND python3 ${SL_COURSE_PY}/test_grade.py $<TARGET_FILE:shadowlab> ${CMAKE_SOURCE_DIR} ${SL_COURSE_DIR}/grade)
  set_tests_properties(course_grade PROPERTIES LABELS course TIMEOUT 1200)
  # Feedback that tells the student what to fix: failing figures, the mirror's pictures, notes,
  # no instructor path (issue 29).
  add_test(NAME course_feedback
           COMMAND python3 ${SL_COURSE_PY}/test_feedback.py $<TARGET_FILE:shadowlab> ${CMAKE_SOURCE_DIR} ${SL_COURSE_DIR}/feedback)
  set_tests_properties(course_feedback PROPERTIES LABELS course TIMEOUT 1200)
else()
  message(WARNING "chromium not found: course_grade (the feedback pages in a browser) is not run")
endif()
# The roster's columns in grades.csv, records and pages; malformed rosters refused (issue 29).
add_test(NAME course_roster
         COMMAND python3 ${SL_COURSE_PY}/test_roster.py $<TARGET_FILE:shadowlab> ${CMAKE_SOURCE_DIR} ${SL_COURSE_DIR}/roster)
set_tests_properties(course_roster PROPERTIES LABELS course TIMEOUT 600)
# The late policy: a late hand-in loses exactly the policy's points, within the grace nothing.
add_test(NAME course_late
         COMMAND python3 ${SL_COURSE_PY}/test_late.py $<TARGET_FILE:shadowlab> ${CMAKE_SOURCE_DIR} ${SL_COURSE_DIR}/late)
set_tests_properties(course_late PROPERTIES LABELS course TIMEOUT 1200)
# A platform failure is never a score, and a rerun grades exactly what changed (issue 25).
add_test(NAME course_not_graded
         COMMAND python3 ${SL_COURSE_PY}/test_regrade.py $<TARGET_FILE:shadowlab> ${CMAKE_SOURCE_DIR} ${SL_COURSE_DIR}/regrade)
set_tests_properties(course_not_graded PROPERTIES LABELS course TIMEOUT 1200)
# The same grades with a busy loop pinned to every core (issue 25).
add_test(NAME course_load
         COMMAND python3 ${SL_COURSE_PY}/test_load.py $<TARGET_FILE:shadowlab> ${CMAKE_SOURCE_DIR} ${SL_COURSE_DIR}/load)
set_tests_properties(course_load PROPERTIES LABELS "course;load" TIMEOUT 2400 RUN_SERIAL TRUE)
# What grade shares across a class changes no figure: rows identical to check alone (issue 28).
add_test(NAME course_same_figures
         COMMAND python3 ${SL_COURSE_PY}/test_same_figures.py $<TARGET_FILE:shadowlab> ${CMAKE_SOURCE_DIR} ${SL_COURSE_DIR}/same-figures)
set_tests_properties(course_same_figures PROPERTIES LABELS course TIMEOUT 1500)
add_test(NAME course_autograder
         COMMAND python3 ${SL_COURSE_PY}/test_autograder.py $<TARGET_FILE:shadowlab> ${CMAKE_SOURCE_DIR} ${SL_COURSE_DIR}/autograder)
set_tests_properties(course_assignment_errors course_zip_safety PROPERTIES LABELS course TIMEOUT 300)
set_tests_properties(course_release_core course_release_legacy course_autograder PROPERTIES LABELS course TIMEOUT 1200)
# Hostile and careless class folders: links, junk, names, resume, overlaps, zips, the lock (issue 26).
add_test(NAME course_class_hostile
         COMMAND python3 ${SL_COURSE_PY}/test_class_hostile.py $<TARGET_FILE:shadowlab> ${CMAKE_SOURCE_DIR} ${SL_COURSE_DIR}/class-hostile)
set_tests_properties(course_class_hostile PROPERTIES LABELS course TIMEOUT 1200)
# A link planted at any name grade writes under --out is refused; nothing outside changes (issue 38).
add_test(NAME course_out_links
         COMMAND python3 ${SL_COURSE_PY}/test_out_links.py $<TARGET_FILE:shadowlab> ${CMAKE_SOURCE_DIR} ${SL_COURSE_DIR}/out-links)
set_tests_properties(course_out_links PROPERTIES LABELS course TIMEOUT 300)
# A worker killed from outside is NOT GRADED (exit 3), and the rerun grades it (issue 38).
add_test(NAME course_worker_killed
         COMMAND python3 ${SL_COURSE_PY}/test_worker_killed.py $<TARGET_FILE:shadowlab> ${CMAKE_SOURCE_DIR} ${SL_COURSE_DIR}/worker-killed)
set_tests_properties(course_worker_killed PROPERTIES LABELS course TIMEOUT 600)
# A record edited by hand in OUT/students/ is graded again, with a line (issue 38).
add_test(NAME course_record_hash
         COMMAND python3 ${SL_COURSE_PY}/test_record_hash.py $<TARGET_FILE:shadowlab> ${CMAKE_SOURCE_DIR} ${SL_COURSE_DIR}/record-hash)
set_tests_properties(course_record_hash PROPERTIES LABELS course TIMEOUT 900)
# Times, rosters and Gradescope's metadata that once crashed or passed unchecked (issue 38).
add_test(NAME course_hostile_text
         COMMAND python3 ${SL_COURSE_PY}/test_hostile_text.py $<TARGET_FILE:shadowlab> ${CMAKE_SOURCE_DIR} ${SL_COURSE_DIR}/hostile-text)
set_tests_properties(course_hostile_text PROPERTIES LABELS course TIMEOUT 900)
# A student's page at a glance: the stages' overview, captions, TIMEOUT's cause, source notes (issue 39).
add_test(NAME course_student_page
         COMMAND python3 ${SL_COURSE_PY}/test_student_page.py $<TARGET_FILE:shadowlab> ${CMAKE_SOURCE_DIR} ${SL_COURSE_DIR}/student-page)
set_tests_properties(course_student_page PROPERTIES LABELS course TIMEOUT 600)
# Names as the file system gives them (not UTF-8) and a full disk said in one line (issue 39).
add_test(NAME course_names_disks
         COMMAND python3 ${SL_COURSE_PY}/test_names_disks.py $<TARGET_FILE:shadowlab> ${CMAKE_SOURCE_DIR} ${SL_COURSE_DIR}/names-disks)
set_tests_properties(course_names_disks PROPERTIES LABELS course TIMEOUT 300)
# A student's own check report handed in: compared with the grade, never a score (issue 36).
add_test(NAME course_own_check
         COMMAND python3 ${SL_COURSE_PY}/test_own_check.py $<TARGET_FILE:shadowlab> ${CMAKE_SOURCE_DIR} ${SL_COURSE_DIR}/own-check)
set_tests_properties(course_own_check PROPERTIES LABELS course TIMEOUT 300)
