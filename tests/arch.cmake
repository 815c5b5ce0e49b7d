# The layering test: every #include "..." of src/ against the floors of docs/architecture.md
# (tests/arch/check_layers.py, python3's standard library only; well under a second).
find_package(Python3 REQUIRED COMPONENTS Interpreter)
add_test(NAME architecture_layers
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/arch/check_layers.py
                 --repo ${CMAKE_SOURCE_DIR})
set_tests_properties(architecture_layers PROPERTIES LABELS unit TIMEOUT 60)

# No stage id outside src/stages/: every string literal of src/ against stage_list.h's ids
# (tests/arch/check_stage_ids.py, docs/architecture.md "Stage ids outside src/stages/"; well
# under a second).
add_test(NAME stage_ids_outside_stages
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/arch/check_stage_ids.py
                 --repo ${CMAKE_SOURCE_DIR})
set_tests_properties(stage_ids_outside_stages PROPERTIES LABELS unit TIMEOUT 60)
