"""The graded rows of a `shadowlab check --report` file, flat: the report nests them in stages
(`stages[].rows[]`, docs/check.md "The report")."""


def report_rows(report):
    return [row for stage in report["stages"] for row in stage["rows"]]
