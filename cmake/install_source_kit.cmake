# `cmake --install`: the source kit's files (source_kit.txt, written by the build) into
# share/shadowlab at their places in the source tree, so the installed copy can write the
# Gradescope zip. SL_SOURCE_KIT, SL_KIT_FROM and SL_KIT_TO are set by CMakeLists.txt.
if(NOT EXISTS "${SL_SOURCE_KIT}")
  message(FATAL_ERROR "${SL_SOURCE_KIT} is missing: build the program (its source_kit target) first")
endif()
file(STRINGS "${SL_SOURCE_KIT}" sl_kit_files)
foreach(f IN LISTS sl_kit_files)
  get_filename_component(dir "${f}" DIRECTORY)
  file(INSTALL DESTINATION "${SL_KIT_TO}/${dir}" TYPE FILE USE_SOURCE_PERMISSIONS
       FILES "${SL_KIT_FROM}/${f}")
endforeach()
