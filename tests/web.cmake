# The browser edition in headless Chromium (tests/web/web_browser.py): every core stage through
# the page's keys against the native `render` of the same stage and camera. Reads the site
# scripts/web.sh built (build-web/site beside this build, or $SHADOWLAB_WEB_SITE); skipped with
# the reason when there is none, or no Chromium, chromedriver or Selenium. About 25 s here.
set(SL_WEB_SITE ${CMAKE_SOURCE_DIR}/build-web/site)
if(DEFINED ENV{SHADOWLAB_WEB_SITE})
  set(SL_WEB_SITE $ENV{SHADOWLAB_WEB_SITE})
endif()
# One browser test: tests/web/SCRIPT against SITE, writing to OUT in this build, with ARGN. Each
# runs alone (Chromium's SwiftShader takes both cores while it draws) and is skipped (exit 77)
# with its reason where there is no site, Chromium, chromedriver or Selenium.
function(sl_web_test name script site out timeout)
  add_test(NAME ${name}
           COMMAND ${SYSTEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/web/${script}
                   --site ${site} --shadowlab $<TARGET_FILE:shadowlab>
                   --out ${CMAKE_BINARY_DIR}/${out} ${ARGN})
  set_tests_properties(${name} PROPERTIES LABELS web SKIP_RETURN_CODE 77 TIMEOUT ${timeout}
                       RUN_SERIAL TRUE)
endfunction()
sl_web_test(web_browser web_browser.py ${SL_WEB_SITE} web 420)
# The page's check against native `check` (tests/web/web_check.py): our shaders' `check --all`
# and the first hand-in of each stage and expected verdict of the corpus (21 of its 103 core
# cases), the same seed on both sides: every row's verdict equal, an ERROR's line too. The whole
# corpus (--per-verdict 0) is run by hand (docs/web.md). The site is served over HTTP, as a
# course serves it: the page's Web Workers trace every reference (none on the page's thread);
# the other check tests open it from the disk, where the page traces on its own thread. About
# 3 min here.
sl_web_test(web_check web_check.py ${SL_WEB_SITE} web_check 600 --students . --per-verdict 1 --serve)
# "Everything due" in the page against native `check --assignment` (the shipped example
# assignments/lab4.json, as a course publishes it beside the page): our shaders and margin's first
# hand-in of each expected verdict, every row's verdict and the score equal. About 40 s here.
sl_web_test(web_check_assignment web_check.py ${SL_WEB_SITE} web_check_assignment 300
            --assignment ${CMAKE_SOURCE_DIR}/assignments/lab4.json --students "^margin_"
            --per-verdict 1)
# The student edition's site (build-web/site-student, what a course publishes for its
# students): no line of a solution region in it, our stubbed shaders score 0 there, and at the
# last seed whose drawn figures it ships, margin's hand-ins (the first of each expected verdict)
# get native's verdicts row for row.
sl_web_test(web_student_edition web_check.py ${SL_WEB_SITE}-student web_student_edition 300
            --student-edition --students "^margin_(.*)$" --per-verdict 1 --no-ours)
# The page does what the window does (tests/web/web_split_hud.py): the HUD lines over the page's
# picture are the native window's (run under Xvfb with the same keys), and `s` splits the canvas
# into the halves the window draws, each the native render of its settings. 10 to 16 s here.
sl_web_test(web_split_hud web_split_hud.py ${SL_WEB_SITE} web_split_hud 300)
# A shader that loops never freezes the page (tests/web/web_loop.py, docs/web.md): a looping
# depth hand-in stopped by the loop budget, named, the page still drawing; the page's check
# --all over it: the depth rows TIMEOUT naming the file, every other stage graded. About 30 s.
sl_web_test(web_loop web_loop.py ${SL_WEB_SITE} web_loop 300)
# A WebGL context lost during the page's check (tests/web/web_lost_context.py, docs/web.md): the
# check ends, the stages done before keep their verdicts, the rest are NOT GRADED naming the loss
# (never FAIL or ERROR), exit 3; a reload recovers. About 15 s.
sl_web_test(web_lost_context web_lost_context.py ${SL_WEB_SITE} web_lost_context 300)
