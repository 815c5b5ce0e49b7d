#!/usr/bin/env python3
"""The page's check against native `check`, timed (docs/web.md "Check in the page"): for each
core stage (`check --stage S`) and for `check --all --glsl core`, our shaders, the page's check in
headless Chromium (SwiftShader) and native `check` (llvmpipe) run alternately --reps times on
this machine. Prints each pair's ratio and the median with its spread, writes bench_check.json.
A benchmark, not a test: it asserts nothing about time.
usage: bench_check.py --site build-web/site --shadowlab build/shadowlab --out DIR [--reps 3]
[--serve]"""
import json
import pathlib
import statistics
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import web_browser  # noqa: E402
import web_check  # noqa: E402


def main():
    ap = web_browser.site_arguments()
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--seed", type=int, default=4242)
    ap.add_argument("--only", default="", help="these runs only (comma-separated: margin,all)")
    ap.add_argument("--serve", action="store_true",
                    help="serve the site over HTTP: the page's Web Workers trace the references")
    args = ap.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    driver = web_browser.browser()
    driver.set_script_timeout(1800)
    results = {}
    try:
        address = web_browser.serve(args.site) if args.serve else None
        if not web_browser.open_page(driver, args.site, address) or (
                args.serve and not web_check.wait_for_tracers(driver)):
            print("bench: the page (or its tracers) never became ready")
            return 1
        runs = driver.execute_script(
            "return shadowlab.stages.filter(s => !s.nativeOnly).map(s => s.id)") + ["all"]
        if args.only:
            runs = [r for r in runs if r in args.only.split(",")]
        for what in runs:
            ratios, page_s, native_s = [], [], []
            for rep in range(args.reps):
                got = driver.execute_async_script(web_check.RUN, what, str(args.seed))
                if got.get("error"):
                    print(f"bench: {what}: the page says {got['error']!r}")
                    break
                _, seconds, _ = web_check.native_check(args.shadowlab, what, None, args.seed,
                                                    out / f"native_{what}.json")
                page_s.append(got["seconds"])
                native_s.append(seconds)
                ratios.append(got["seconds"] / seconds)
            if not ratios:
                continue
            results[what] = {"page_s": page_s, "native_s": native_s, "ratios": ratios,
                             "median_ratio": statistics.median(ratios)}
            print(f"bench: check {what:9} page {statistics.median(page_s):6.1f} s, native "
                  f"{statistics.median(native_s):5.1f} s: {statistics.median(ratios):.1f}x "
                  f"(pairs {min(ratios):.1f}x to {max(ratios):.1f}x, {len(ratios)} alternating)")
    finally:
        driver.quit()
    (out / "bench_check.json").write_text(json.dumps(results, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
