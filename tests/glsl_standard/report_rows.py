"""The rows of a `check --report` file, however the report nests them (shared by this folder's
runners)."""


def rows(node):
    """Every report row: a dict with a stage, a verdict and a message."""
    if isinstance(node, dict):
        if "stage" in node and "verdict" in node and "message" in node:
            yield node
        for value in node.values():
            yield from rows(value)
    elif isinstance(node, list):
        for value in node:
            yield from rows(value)
