# Khronos' reference GLSL front end (Debian: glslang-dev), linked into the program: every shader
# is validated by it before a driver compiles one (src/gl/glsl_standard.cpp), so what the standard
# forbids is refused on every driver alike. Defines the interface target `sl_glslang`.
#
# What the packages ship differs by version (checked, not guessed):
#   glslang 12 (Debian 12) .. 16 (Debian testing): a CMake package, glslang::glslang, and
#     glslang/Public/ResourceLimits.h with GetDefaultResources() in glslang-default-resource-limits;
#   glslang 11 (Ubuntu 22.04): no CMake package file we can rely on and no installed header for
#     the default limits: the libraries are found one by one and the limits are our own
#     (src/gl/glsl_standard.cpp, SHADOWLAB_GLSLANG_RESOURCES_HEADER unset).
# From glslang 14 on only the public API is installed (no syntax-tree headers): the source rules
# read glslang's own printout of the tree (EShMsgAST), which every version has.
add_library(sl_glslang INTERFACE)
find_package(glslang CONFIG QUIET)
if(TARGET glslang::glslang)
  set(SL_GLSLANG_LINK glslang::glslang)
  if(TARGET glslang::glslang-default-resource-limits)
    list(APPEND SL_GLSLANG_LINK glslang::glslang-default-resource-limits)
  endif()
  set(SL_GLSLANG_HOW "CMake package ${glslang_VERSION}")
else()
  find_path(SL_GLSLANG_INCLUDE glslang/Public/ShaderLang.h)
  find_library(SL_GLSLANG_LIB glslang)
  if(NOT SL_GLSLANG_INCLUDE OR NOT SL_GLSLANG_LIB)
    message(FATAL_ERROR "glslang not found: install glslang-dev (scripts/deps.sh does)")
  endif()
  # Static archives that call each other (HLSL <-> MachineIndependent): linked as one group.
  set(SL_GLSLANG_LIBS ${SL_GLSLANG_LIB})
  foreach(part MachineIndependent HLSL GenericCodeGen OGLCompiler OSDependent
               glslang-default-resource-limits)
    find_library(SL_GLSLANG_${part} ${part})
    if(SL_GLSLANG_${part})
      list(APPEND SL_GLSLANG_LIBS ${SL_GLSLANG_${part}})
    endif()
  endforeach()
  target_include_directories(sl_glslang INTERFACE ${SL_GLSLANG_INCLUDE})
  set(CMAKE_REQUIRED_INCLUDES ${SL_GLSLANG_INCLUDE})
  set(SL_GLSLANG_LINK -Wl,--start-group ${SL_GLSLANG_LIBS} -Wl,--end-group Threads::Threads)
  set(SL_GLSLANG_HOW "libraries ${SL_GLSLANG_LIBS}")
endif()
target_link_libraries(sl_glslang INTERFACE ${SL_GLSLANG_LINK})

# The default limits: where the header and its library work, glslang's own; else ours.
include(CheckCXXSourceCompiles)
set(CMAKE_REQUIRED_LIBRARIES ${SL_GLSLANG_LINK})
check_cxx_source_compiles([[
#include <glslang/Public/ResourceLimits.h>
int main() { return GetDefaultResources()->maxDrawBuffers > 0 ? 0 : 1; }
]] SHADOWLAB_GLSLANG_RESOURCES_HEADER)
unset(CMAKE_REQUIRED_LIBRARIES)
unset(CMAKE_REQUIRED_INCLUDES)
if(SHADOWLAB_GLSLANG_RESOURCES_HEADER)
  target_compile_definitions(sl_glslang INTERFACE SHADOWLAB_GLSLANG_RESOURCES_HEADER=1)
endif()
message(STATUS "glslang: ${SL_GLSLANG_HOW}; default limits from glslang: "
               "${SHADOWLAB_GLSLANG_RESOURCES_HEADER}")

# Debian's glslang is built without RTTI, so UBSan's vptr check (the sanitizer build,
# scripts/sanitizers.sh) would reference typeinfo its library does not have. The one file that
# holds glslang's objects is compiled without that one check; every other check stays.
if(CMAKE_CXX_FLAGS MATCHES "-fsanitize=[^ ]*undefined")
  set_property(SOURCE src/gl/glsl_standard.cpp APPEND PROPERTY COMPILE_OPTIONS -fno-sanitize=vptr)
endif()
