# `bench` and `sweep` on a small setting: they run, and their CSV has every column filled.
# (Speed targets are read from a full `shadowlab bench`, never asserted in a test.)
set(SL_BENCH_DIR ${CMAKE_BINARY_DIR}/bench-ci)
set(SL_CHECK_CSV ${CMAKE_CURRENT_SOURCE_DIR}/bench/check_csv.py)
# A command's exit code and its output, both (PASS_REGULAR_EXPRESSION alone ignores the exit code).
set(SL_EXPECT_RUN python3 ${CMAKE_CURRENT_SOURCE_DIR}/check/expect_run.py)
# Every test deletes what it reads before the run that writes it: a file left by an earlier run
# cannot pass.
add_test(NAME bench_quick
         COMMAND sh -c "rm -f ${SL_BENCH_DIR}/bench.csv ${SL_BENCH_DIR}/bench.json ${SL_BENCH_DIR}/error-vs-time.png && $<TARGET_FILE:shadowlab> bench --quick --frames 2 --out ${SL_BENCH_DIR} && python3 ${SL_CHECK_CSV} ${SL_BENCH_DIR}/bench.csv 60 frame_ms frame_iqr_ms shadow_ms lit_ms mirror_ms ratio_to_phong error_pct && test -s ${SL_BENCH_DIR}/bench.json && test -s ${SL_BENCH_DIR}/error-vs-time.png && python3 ${CMAKE_CURRENT_SOURCE_DIR}/bench/check_figure_headers.py ${SL_BENCH_DIR}/bench.json")
set_tests_properties(bench_quick PROPERTIES LABELS bench TIMEOUT 300)
foreach(axis elevation margin offset near-far map-size)
  add_test(NAME sweep_${axis}
           COMMAND sh -c "rm -f ${SL_BENCH_DIR}/sweep-${axis}.csv ${SL_BENCH_DIR}/sweep-${axis}-breaks.csv && $<TARGET_FILE:shadowlab> sweep ${axis} --quick --size 160x120 --out ${SL_BENCH_DIR} && python3 ${SL_CHECK_CSV} ${SL_BENCH_DIR}/sweep-${axis}.csv 8 $<$<STREQUAL:${axis},elevation>:--na-below 3> value error_pct false_shadow_pct false_lit_pct && python3 ${SL_CHECK_CSV} ${SL_BENCH_DIR}/sweep-${axis}-breaks.csv 2 best_value best_error_pct")
  set_tests_properties(sweep_${axis} PROPERTIES LABELS bench TIMEOUT 300)
endforeach()
# A misspelt axis: exit 2 and the closest axis suggested.
add_test(NAME sweep_unknown_axis
         COMMAND ${SL_EXPECT_RUN} --exit 2 --output "did you mean 'elevation'"
                 -- $<TARGET_FILE:shadowlab> sweep elevaton --out ${SL_BENCH_DIR})
set_tests_properties(sweep_unknown_axis PROPERTIES LABELS bench)
# `bench --instructions` (the child under callgrind counts every 640x480 row, phong included,
# so instructions per frame and their ratio to phong are numbers on every row) is run by
# docs/bench.md's own command, `docs_long_bench`, whose mark checks those columns and the chart:
# one callgrind run of the bench in CI, not two.
# The equal-accuracy search: one row per method searched, each either the cheapest configuration
# reaching edge p95 <= 2 px and error <= 0.1 % or the closest one marked unreached, with its
# figures; a reached row must really meet the bar.
add_test(NAME bench_equal_accuracy
         COMMAND sh -c "rm -rf ${SL_BENCH_DIR}/equal && $<TARGET_FILE:shadowlab> bench --quick --frames 2 --equal-accuracy --only peers/normal --out ${SL_BENCH_DIR}/equal && python3 -c \"import json,sys; e=json.load(open('${SL_BENCH_DIR}/equal/bench.json'))['equal_accuracy']; print(e); ok=len(e)==1 and e[0]['method']=='peers/normal-offset' and e[0]['error_pct'] is not None and 'light-fit=' in e[0]['settings'] and (not e[0]['reached'] or (e[0]['edge_p95_px']<=2 and e[0]['error_pct']<=0.1)); sys.exit(0 if ok else 1)\"")
set_tests_properties(bench_equal_accuracy PROPERTIES LABELS bench TIMEOUT 300)
