# The bad-input corpus (tests/bad_inputs/cases.txt and generated cases): every malformed option,
# scene, shader and output path gets a one-line error and the contract's exit code; no crash,
# hang or partial file. One ctest test runs them all and reports every failure.
find_package(Python3 REQUIRED COMPONENTS Interpreter)
add_test(NAME bad_inputs
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/bad_inputs/run_cases.py
                 $<TARGET_FILE:shadowlab>)
set_tests_properties(bad_inputs PROPERTIES LABELS command TIMEOUT 1200)
