# Adding a stage (docs/adding-a-stage.md): the program built again from its own sources with one
# more stage, tests/stage/throwaway.cpp, registered by the one line `SL_STAGE(throwaway)` added
# to a copy of src/stages/stage_list.h (which this build includes before the real one), so
# nothing of src/ is edited. Three objects and a link on top of sl_app, and a test of about
# ten seconds: it lists, renders and checks the stage (tests/stage/add_stage.py).
set(SL_EXTRA_STAGE_DIR ${CMAKE_CURRENT_BINARY_DIR}/extra_stage)
file(READ ${CMAKE_SOURCE_DIR}/src/stages/stage_list.h SL_REAL_STAGE_LIST)
file(CONFIGURE OUTPUT ${SL_EXTRA_STAGE_DIR}/stages/stage_list.h
     CONTENT "${SL_REAL_STAGE_LIST}SL_STAGE(throwaway)\n" @ONLY)
configure_file(${CMAKE_SOURCE_DIR}/src/stages/registry.cpp ${SL_EXTRA_STAGE_DIR}/registry.cpp
               COPYONLY)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
             ${CMAKE_SOURCE_DIR}/src/stages/stage_list.h)
# The copy of registry.cpp defines every symbol of the real one, so the linker takes none from
# sl_gl's registry object; the real stages come from sl_gl as the list names them.
add_executable(shadowlab_extra_stage ${CMAKE_SOURCE_DIR}/src/app/main.cpp
               ${SL_EXTRA_STAGE_DIR}/registry.cpp ${CMAKE_CURRENT_SOURCE_DIR}/stage/throwaway.cpp)
target_include_directories(shadowlab_extra_stage BEFORE PRIVATE ${SL_EXTRA_STAGE_DIR})
target_link_libraries(shadowlab_extra_stage PRIVATE sl_app)
target_compile_options(shadowlab_extra_stage PRIVATE ${SHADOWLAB_WARNINGS})
add_test(NAME adding_a_stage
         COMMAND python3 ${CMAKE_CURRENT_SOURCE_DIR}/stage/add_stage.py
                 $<TARGET_FILE:shadowlab_extra_stage> ${CMAKE_CURRENT_BINARY_DIR}/extra_stage_run)
set_tests_properties(adding_a_stage PROPERTIES LABELS check TIMEOUT 300)
