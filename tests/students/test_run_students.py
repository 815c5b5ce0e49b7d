#!/usr/bin/env python3
"""The runner's reading of a report: a stage is as bad as its worst row, nested per-view and
per-lesson rows included, other stages' rows ignored; and case.json is validated."""
import json
import os
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True  # keep the corpus folder clean
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run_students as rs  # noqa: E402


def worst(report, stage):
    rows = rs.rows_of(report.get("results", []), stage)
    return max(rows, key=lambda r: rs.SEVERITY.get(r.get("verdict"), 3)) if rows else None


class RowsTest(unittest.TestCase):
    def test_flat_rows(self):
        report = {"results": [{"stage": "rgb", "verdict": "PASS", "figures": {}},
                              {"stage": "depth", "verdict": "FAIL", "figures": {}}]}
        self.assertEqual(worst(report, "rgb")["verdict"], "PASS")
        self.assertEqual(worst(report, "depth")["verdict"], "FAIL")

    def test_nested_views_and_lessons(self):
        report = {"results": [{"stage": "margin", "verdict": "PASS", "lessons": [
            {"lesson": "constant", "verdict": "PASS", "views": [{"view": "lecture", "verdict": "PASS"}]},
            {"lesson": "slope", "verdict": "PASS", "views": [
                {"view": "grazing", "verdict": "FAIL", "figures": {"false_shadow_pct": 7.5}}]}]}]}
        row = worst(report, "margin")
        self.assertEqual(row["verdict"], "FAIL")
        self.assertIn("view=grazing", rs.describe(row))
        self.assertIn("false_shadow_pct=7.5", rs.describe(row))
        # With reasons (the verdict's bounds as data), the judged figures and each missed bound.
        row["reasons"] = [{"figure": "false_shadow_pct", "value": 7.5, "side": "<=", "bound": 1,
                           "passed": False},
                          {"figure": "edge_p95_px", "value": 1.25, "side": "<=", "bound": 2,
                           "passed": True}]
        self.assertIn("false_shadow_pct=7.5 (not <= 1) edge_p95_px=1.25", rs.describe(row))

    def test_error_outranks_fail(self):
        report = {"results": [{"stage": "bias", "verdict": "FAIL"},
                              {"stage": "bias", "verdict": "ERROR", "message": "lit.frag:3: x"}]}
        self.assertEqual(worst(report, "bias")["verdict"], "ERROR")

    def test_case_json_validated(self):
        with tempfile.TemporaryDirectory() as d:
            os.makedirs(os.path.join(d, "c"))
            with open(os.path.join(d, "c", "case.json"), "w") as f:
                json.dump({"stage": "rgb", "tree": "core", "verdict": "MAYBE", "why": "x"}, f)
            old = rs.HERE
            rs.HERE = d
            try:
                with self.assertRaises(ValueError):
                    rs.load_case("c")
            finally:
                rs.HERE = old

    def test_every_case_is_valid(self):
        names = rs.all_cases()
        self.assertGreaterEqual(len(names), 45)
        for n in names:
            case = rs.load_case(n)
            files = [f for _, _, fs in os.walk(case["folder"]) for f in fs if f != "case.json"]
            if case["verdict"] != "MISSING":  # a MISSING case may hand in nothing at all
                self.assertTrue(files, f"{n}: no shader files")

    def test_missing_outranks_pass(self):
        report = {"results": [{"stage": "margin", "verdict": "MISSING"}]}
        self.assertEqual(worst(report, "margin")["verdict"], "MISSING")


if __name__ == "__main__":
    unittest.main()
