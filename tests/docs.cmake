# Docs as tests (tests/docs/run_docs.py): every command README.md and docs/*.md show runs against
# this build, and what the text says they print is compared. One test per page, label `docs`;
# the commands marked `long` (over about a minute here) in a test of their own, label `docs-long`.
find_package(Python3 REQUIRED COMPONENTS Interpreter)
file(GLOB SL_DOC_PAGES CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/docs/*.md)
set(SL_DOCS_RUN ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/docs/run_docs.py
    --exe $<TARGET_FILE:shadowlab> --repo ${CMAKE_SOURCE_DIR})
foreach(page ${CMAKE_SOURCE_DIR}/README.md ${SL_DOC_PAGES})
  get_filename_component(name ${page} NAME_WE)
  add_test(NAME docs_${name} COMMAND ${SL_DOCS_RUN} ${page})
  set_tests_properties(docs_${name} PROPERTIES LABELS docs TIMEOUT 900)
  # which pages have long commands: asked of the runner, so a mark it reads is never left out
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${page}
               ${CMAKE_CURRENT_SOURCE_DIR}/docs/run_docs.py ${CMAKE_CURRENT_SOURCE_DIR}/docs/doc_page.py)
  execute_process(COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/docs/run_docs.py
                          --exe unused --repo ${CMAKE_SOURCE_DIR} --count-long ${page}
                  OUTPUT_VARIABLE long_count RESULT_VARIABLE rc OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT rc EQUAL 0)
    message(WARNING "docs-test marks of ${page}: ${long_count}")  # docs_${name} fails with it
  endif()
  if(long_count GREATER 0)
    add_test(NAME docs_long_${name} COMMAND ${SL_DOCS_RUN} --long ${page})
    set_tests_properties(docs_long_${name} PROPERTIES LABELS docs-long TIMEOUT 1800)
  endif()
endforeach()
