# The browser edition (GUIDE section 9, docs/web.md): configured with Debian's emscripten
# (`emcmake cmake`, driven by scripts/web.sh), it compiles the same scene, math, GL layer,
# renderer and stages as the native program for WebGL 2 into one self-contained .js
# (-sSINGLE_FILE: opens from file:// too) and our own page, in <build>/site/.
# Debian's glm and nlohmann-json headers are header-only: reached through links, since
# -I/usr/include would mix the host's C library into emscripten's.
set(SL_WEB_INCLUDE ${CMAKE_BINARY_DIR}/web_include)
file(MAKE_DIRECTORY ${SL_WEB_INCLUDE})
foreach(header_dir glm nlohmann)
  if(NOT EXISTS /usr/include/${header_dir})
    message(FATAL_ERROR "/usr/include/${header_dir} missing: install libglm-dev nlohmann-json3-dev")
  endif()
  file(CREATE_LINK /usr/include/${header_dir} ${SL_WEB_INCLUDE}/${header_dir} SYMBOLIC)
endforeach()
foreach(stb_header stb_easy_font.h stb_image_write.h)
  file(CREATE_LINK /usr/include/stb/${stb_header} ${SL_WEB_INCLUDE}/${stb_header} SYMBOLIC)
endforeach()
# Written only when it differs: a new date on it at every configure rebuilt every object.
file(CONFIGURE OUTPUT ${SL_WEB_INCLUDE}/shadowlab_glad.h
     CONTENT "#pragma once\n#include \"gl/gl_es3.h\"\n")

find_program(SYSTEM_PYTHON3 python3 PATHS /usr/bin NO_DEFAULT_PATH REQUIRED)

# glslang and SPIRV-Cross from Debian's source packages of the versions installed here
# (scripts/web_sources.py), compiled to WebAssembly: the page accepts GLSL by the same glslang as
# `check` (gl/glsl_standard.cpp) and translates it to ESSL 3.00 as Debian's spirv-cross tool does.
execute_process(
  COMMAND ${SYSTEM_PYTHON3} ${CMAKE_SOURCE_DIR}/scripts/web_sources.py ${CMAKE_BINARY_DIR}/debian-src
  OUTPUT_VARIABLE SL_WEB_SOURCE_DIRS RESULT_VARIABLE SL_WEB_SOURCES_RESULT)
if(NOT SL_WEB_SOURCES_RESULT EQUAL 0)
  message(FATAL_ERROR "glslang and SPIRV-Cross sources could not be fetched (above)")
endif()
string(STRIP "${SL_WEB_SOURCE_DIRS}" SL_WEB_SOURCE_DIRS)
string(REPLACE "\n" ";" SL_WEB_SOURCE_DIRS "${SL_WEB_SOURCE_DIRS}")
list(GET SL_WEB_SOURCE_DIRS 0 SL_WEB_GLSLANG_SOURCE)
list(GET SL_WEB_SOURCE_DIRS 1 SL_WEB_SPIRV_CROSS_SOURCE)
add_compile_options(-fexceptions)  # SPIRV-Cross reports a failed translation by throwing
foreach(option ENABLE_HLSL ENABLE_OPT ENABLE_GLSLANG_BINARIES ENABLE_CTEST BUILD_EXTERNAL
               ENABLE_SPVREMAPPER ENABLE_PCH SPIRV_CROSS_CLI SPIRV_CROSS_ENABLE_TESTS
               SPIRV_CROSS_ENABLE_HLSL SPIRV_CROSS_ENABLE_MSL SPIRV_CROSS_ENABLE_CPP
               SPIRV_CROSS_ENABLE_REFLECT SPIRV_CROSS_ENABLE_C_API SPIRV_CROSS_ENABLE_UTIL)
  set(${option} OFF CACHE BOOL "the browser edition needs only the GLSL front end" FORCE)
endforeach()
set(SKIP_GLSLANG_INSTALL ON CACHE BOOL "" FORCE)
set(SPIRV_CROSS_SKIP_INSTALL ON CACHE BOOL "" FORCE)
add_subdirectory(${SL_WEB_GLSLANG_SOURCE} glslang EXCLUDE_FROM_ALL)
add_subdirectory(${SL_WEB_SPIRV_CROSS_SOURCE} spirv-cross EXCLUDE_FROM_ALL)

# What runs in the browser: the lecture (scene, renderer, stages, lecture/: lessons, split, HUD)
# and `check` in the page (the reference tracer, the figures, the plan, judge and record:
# grade/check_steps.h; an assignment's plan: course/assignment.h, course/student_grade.h), drawn
# into the page's WebGL context (platform/webgl_*); none of the desktop's sandbox, libpng (stb
# writes the page's pictures: io/png_web.cpp), GL loader or OSMesa/EGL/X11 contexts.
file(GLOB SL_WEB_SOURCES CONFIGURE_DEPENDS
     src/io/*.cpp src/math/*.cpp src/scene/*.cpp src/gl/*.cpp src/render/*.cpp src/stages/*.cpp
     src/reference/*.cpp src/metrics/*.cpp src/eval/evaluator.cpp src/eval/trace_view.cpp
     src/platform/webgl_context.cpp src/platform/webgl_headless.cpp src/platform/headless.cpp
     src/platform/framebuffer_target.cpp src/lecture/*.cpp
     src/grade/intake.cpp src/grade/check_run.cpp src/grade/check_steps.cpp src/grade/check_plan.cpp
     src/grade/judge.cpp src/grade/case_judge.cpp src/grade/status.cpp src/grade/bounds.cpp src/grade/formats.cpp src/grade/record.cpp
     src/grade/plan.cpp src/grade/reports.cpp src/web/*.cpp
     src/course/assignment.cpp src/course/assignment_meaning.cpp src/course/json_lines.cpp
     src/course/student_grade.cpp src/gradebook/late_policy.cpp src/gradebook/csv.cpp
     src/gradebook/iso_time.cpp)
list(FILTER SL_WEB_SOURCES EXCLUDE REGEX
     "/(io/png|gl/glsl_for_desktop|gl/loader|metrics/callgrind|metrics/timing)\\.cpp$")
list(APPEND SL_WEB_SOURCES ${SL_WEB_GLSLANG_SOURCE}/StandAlone/ResourceLimits.cpp)

file(GLOB_RECURSE SL_WEB_SHADERS CONFIGURE_DEPENDS shaders_core/* scenes/* slides_examples/*)
# The stages' data: the lessons' bounds (expectations.json), the displaced views' and the drawn
# rows' figures of our shaders (check's; a student edition judges by them).
file(GLOB SL_WEB_STAGE_DATA CONFIGURE_DEPENDS src/stages/*.json)

# The page's objects, compiled once for both sites (below), which differ only in the data
# embedded when they are linked.
add_library(shadowlab_web_objects OBJECT ${SL_WEB_SOURCES})
target_include_directories(shadowlab_web_objects PRIVATE src)
target_include_directories(shadowlab_web_objects SYSTEM PRIVATE ${SL_WEB_INCLUDE}  # Debian's
                           ${SL_WEB_GLSLANG_SOURCE} ${SL_WEB_SPIRV_CROSS_SOURCE})
target_compile_definitions(shadowlab_web_objects PRIVATE GLM_FORCE_CTOR_INIT
                           SHADOWLAB_GLSLANG_RESOURCES_HEADER=1)
target_link_libraries(shadowlab_web_objects PRIVATE glslang SPIRV spirv-cross-glsl)
set_property(SOURCE src/io/data_paths.cpp APPEND PROPERTY  # the embedded data (web_main.cpp)
             COMPILE_DEFINITIONS SHADOWLAB_SOURCE_DIR="/data")
target_compile_options(shadowlab_web_objects PRIVATE -Wall -Wextra -Wno-unused-parameter
                       -fexceptions)

# One site: SITE/index.html and SITE/shadowlab.js with DATA embedded (our shaders from SHADERS,
# scenes, lessons, bounds). PREPARE: commands that write SHADERS first; DEPENDS: what they read.
function(sl_web_site target site data shaders)
  cmake_parse_arguments(SITE "" "" "PREPARE;DEPENDS" ${ARGN})
  add_custom_command(
    OUTPUT ${data}/shaders_core.stamp
    COMMAND ${CMAKE_COMMAND} -E rm -rf ${data}
    ${SITE_PREPARE}
    COMMAND ${CMAKE_COMMAND} -E copy_directory ${shaders} ${data}/shaders_core
    COMMAND ${CMAKE_COMMAND} -E copy_directory ${CMAKE_SOURCE_DIR}/scenes ${data}/scenes
    COMMAND ${CMAKE_COMMAND} -E copy_directory ${CMAKE_SOURCE_DIR}/slides_examples
            ${data}/slides_examples
    COMMAND ${CMAKE_COMMAND} -E make_directory ${data}/src/stages
    COMMAND ${CMAKE_COMMAND} -E copy ${SL_WEB_STAGE_DATA} ${data}/src/stages/
    COMMAND ${CMAKE_COMMAND} -E touch ${data}/shaders_core.stamp
    DEPENDS ${SL_WEB_SHADERS} ${SL_WEB_STAGE_DATA} ${SITE_DEPENDS}
    COMMENT "${target}'s data: our shaders (translated in the page), scenes, lessons, bounds"
    VERBATIM)
  add_custom_target(${target}_data DEPENDS ${data}/shaders_core.stamp)
  add_executable(${target} $<TARGET_OBJECTS:shadowlab_web_objects>)
  add_dependencies(${target} ${target}_data)
  # Embedded at link time (--embed-file below): a changed shader, scene or bound relinks it.
  set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS ${data}/shaders_core.stamp)
  target_link_libraries(${target} PRIVATE glslang SPIRV spirv-cross-glsl)
  set_target_properties(${target} PROPERTIES OUTPUT_NAME shadowlab SUFFIX .js
                        RUNTIME_OUTPUT_DIRECTORY ${site})
  target_link_options(${target} PRIVATE
    -fexceptions -sMIN_WEBGL_VERSION=2 -sMAX_WEBGL_VERSION=2 -sSINGLE_FILE=1
    -sALLOW_MEMORY_GROWTH=1 -sEXPORTED_RUNTIME_METHODS=ccall,cwrap,FS,HEAPU8
    "SHELL:--embed-file ${data}@/data")
  # The page and its tracer's worker script: copied whenever they change (not only when the
  # program relinks).
  add_custom_command(
    OUTPUT ${site}/index.html ${site}/trace_worker.js
    COMMAND ${CMAKE_COMMAND} -E copy ${CMAKE_SOURCE_DIR}/src/web/index.html ${site}/index.html
    COMMAND ${CMAKE_COMMAND} -E copy ${CMAKE_SOURCE_DIR}/src/web/trace_worker.js
            ${site}/trace_worker.js
    DEPENDS ${CMAKE_SOURCE_DIR}/src/web/index.html ${CMAKE_SOURCE_DIR}/src/web/trace_worker.js
    VERBATIM)
  add_custom_target(${target}_page ALL DEPENDS ${site}/index.html ${site}/trace_worker.js)
endfunction()

# The lecturer's site: our shaders as the source tree holds them, solutions included.
sl_web_site(shadowlab_web ${CMAKE_BINARY_DIR}/site ${CMAKE_BINARY_DIR}/data
            ${CMAKE_SOURCE_DIR}/shaders_core)
# The student edition's site (what a course publishes for its students): every marked region
# stubbed, as `release --student-edition` writes them, by the native program built beside
# (scripts/web.sh passes it); its check judges as the native student edition does.
set(SHADOWLAB_NATIVE "" CACHE FILEPATH "the native shadowlab that writes the student edition")
if(SHADOWLAB_NATIVE)
  set(SL_WEB_TREES ${CMAKE_BINARY_DIR}/student-trees)
  sl_web_site(shadowlab_web_student ${CMAKE_BINARY_DIR}/site-student
              ${CMAKE_BINARY_DIR}/data-student ${SL_WEB_TREES}/shaders_core
              PREPARE COMMAND ${CMAKE_COMMAND} -E rm -rf ${SL_WEB_TREES}
                      COMMAND ${SHADOWLAB_NATIVE} release --student-edition --out ${SL_WEB_TREES}
              DEPENDS ${SHADOWLAB_NATIVE})
endif()
