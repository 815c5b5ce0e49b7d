# The window's shader trial on EGL (the headless path where there is no OSMesa): its worker is
# forked from the window's thread, on which libglvnd still has the window's GLX context current,
# so EGL refused to make its own current there (EGL_BAD_ACCESS: every student program "failed"
# in Debian testing's chroot). The trial now draws on a thread of its own. A student's folder,
# two frames: no shader error, a screenshot.
if(EGL_FOUND)
  add_test(NAME window_trial_egl
           COMMAND sh -c "d=$(mktemp -d) && mkdir -p $d/margin && cp ${CMAKE_SOURCE_DIR}/shaders_core/margin/lit.frag $d/margin/ && timeout 120 sh ${CMAKE_CURRENT_SOURCE_DIR}/with_xvfb.sh 1280x1024x24 $<TARGET_FILE:shadowlab> window --backend egl --shaders $d --stage margin --frames 2 --screenshot $d/w.png 2>&1; s=$?; test -s $d/w.png; t=$?; rm -rf $d; test $s -eq 0 && test $t -eq 0")
  set_tests_properties(window_trial_egl PROPERTIES LABELS render TIMEOUT 180
                       FAIL_REGULAR_EXPRESSION "shader error|eglMakeCurrent")
endif()
