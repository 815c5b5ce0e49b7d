# Acceptance by the standard (docs/check.md): GLSL that NVIDIA's compiler takes and the standard
# forbids (GLSL 1.20 `in`, texture() in 1.20, Cg's saturate(), an input no output feeds, a type
# mismatch across the stages) is ERROR with glslang's message at the student's file and line,
# exit 2, in `check --stage` and in `check --assignment` alike (tests/glsl_standard/).
add_test(NAME glsl_standard_corpus
         COMMAND python3 ${CMAKE_CURRENT_SOURCE_DIR}/glsl_standard/run_standard.py
                 $<TARGET_FILE:shadowlab> ${CMAKE_BINARY_DIR}/glsl-standard-ci)
set_tests_properties(glsl_standard_corpus PROPERTIES LABELS "check;glsl" TIMEOUT 900)

# Source rules end to end: the report's rows carry `source_notes` (a camera-recognising shader,
# a constant margin; none for a correct submission).
add_test(NAME glsl_source_notes
         COMMAND python3 ${CMAKE_CURRENT_SOURCE_DIR}/glsl_standard/source_notes.py
                 $<TARGET_FILE:shadowlab> ${CMAKE_BINARY_DIR}/glsl-source-notes-ci)
set_tests_properties(glsl_source_notes PROPERTIES LABELS "check;glsl" TIMEOUT 900)
