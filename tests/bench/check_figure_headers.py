#!/usr/bin/env python3
"""scripts/results_md.py names its figure columns from the figure table bench writes into
bench.json (metrics/figures.h): every figure the page shows must be in it, so a figure renamed
there fails here, not on the next scripts/results.sh. usage: check_figure_headers.py BENCH_JSON"""
import json
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "scripts"))
import results_md  # noqa: E402

header = results_md.figure_headers(json.loads(pathlib.Path(sys.argv[1]).read_text()))
for name in results_md.FIGURES_SHOWN:
    print(f"{name}: {header(name)!r}")
