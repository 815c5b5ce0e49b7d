"""A markdown page as docs/README's tests read it: its runnable blocks, inline commands and
docs-test marks (the rules: run_docs.py), and the comparison of a stated output with a real one."""
import re

RUN_LANGS = {"sh", "bash", "console"}
# a mark starts its line (one quoted in the prose, inside backticks, is not a mark)
MARK_RE = re.compile(r"^[ \t]*<!--\s*docs-test:(.*?)-->", re.S | re.M)
FENCE_RE = re.compile(r"^(\s*)```(\w*)\s*$")
INLINE_RE = re.compile(r"`((?:\./build/)?shadowlab [^`]+)`")
STATEMENT_WINDOW = 12
KEYS = ("exit", "skip", "root", "text", "within", "run", "file", "timeout", "expect", "setup", "after",
        "replace")
FLAGS = ("long", "synopsis", "output")
# clauses end at a new line or at "; " before a key (a command may hold "; " of its own)
CLAUSE_SPLIT = re.compile(r"\n|;\s+(?=(?:%s)\b)" % "|".join(KEYS + FLAGS))
DEFAULT_TIMEOUT = 300
LONG_TIMEOUT = 900


class Item:
    def __init__(self, line, kind, text, mark, lang=""):
        self.line, self.kind, self.text, self.mark, self.lang = line, kind, text, mark, lang


def parse_mark(body):
    mark = {"expect": [], "replace": [], "setup": [], "after": [], "flags": set()}
    for clause in CLAUSE_SPLIT.split(body.strip()):
        clause = clause.strip()
        if not clause:
            continue
        key, sep, value = clause.partition(":")
        key, value = key.strip(), value.strip()
        if not sep:
            if key not in FLAGS:
                raise ValueError(f"unknown docs-test flag '{key}'")
            mark["flags"].add(key)
        elif key in ("expect", "setup", "after"):
            mark[key].append(value)
        elif key == "replace":
            old, arrow, new = value.partition("=>")
            if not arrow:
                raise ValueError(f"replace needs 'OLD => NEW', got '{value}'")
            mark["replace"].append((old.strip(), new.strip()))
        elif key in KEYS:
            if key in mark:
                raise ValueError(f"'{key}' given twice in one mark")
            mark[key] = value
        else:
            raise ValueError(f"unknown docs-test key '{key}'")
    return mark


def parse_page(path):
    """The page's items in order: blocks, statements and inline spans, each with its mark."""
    lines = open(path, encoding="utf-8").read().split("\n")
    text = "\n".join(lines)
    # line number (1-based) of every character offset where a mark ends
    marks = []
    for m in MARK_RE.finditer(text):
        end_line = text.count("\n", 0, m.end()) + 1
        marks.append((text.count("\n", 0, m.start()) + 1, end_line, parse_mark(m.group(1))))
    pending = {}  # mark whose next block it applies to, keyed by the line it ends on
    items = []
    for start, end, mark in marks:
        if "text" in mark or ("run" in mark and "file" not in mark):
            within = int(mark.get("within", STATEMENT_WINDOW))
            first = max(0, start - 1 - within)
            item = Item(start, "statement", "\n".join(lines[first:end + within]), mark)
            item.first_line = first + 1
            items.append(item)
        else:
            pending[end] = (start, mark)
    i = 0
    while i < len(lines):
        fence = FENCE_RE.match(lines[i])
        if not fence:
            for span in INLINE_RE.findall(lines[i]):
                items.append(Item(i + 1, "inline", span, None))
            i += 1
            continue
        j = i + 1
        while j < len(lines) and not re.match(r"^\s*```\s*$", lines[j]):
            j += 1
        body = "\n".join(l[len(fence.group(1)):] for l in lines[i + 1:j])
        # a mark applies to the block right after it (blank lines between allowed)
        k, mark, mark_line = i, None, None
        while k > 0 and lines[k - 1].strip() == "":
            k -= 1
        if k in pending:
            mark_line, mark = pending.pop(k)
        lang = fence.group(2)
        if mark and "output" in mark["flags"]:
            # the output of the nearest command above: a block, or a statement's run
            runs = [it for it in items if it.line < mark_line and
                    (it.kind == "block" or it.kind == "statement" and "run" in it.mark)]
            if not runs:
                raise ValueError(f"{path}:{mark_line}: an output mark with no command above it")
            target = max(runs, key=lambda it: it.line)
            target.mark["output_text"], target.mark["output_line"] = body, i + 2
        elif lang in RUN_LANGS or body.startswith("$ ") or mark:
            block = Item(mark_line or i + 1, "block", body, mark or parse_mark(""), lang)
            if body.startswith("$ "):  # a transcript: its output starts on the line after the command
                block.mark["output_line"] = i + 3
            items.append(block)
        i = j + 1
    for end, (start, _) in pending.items():
        raise ValueError(f"{path}:{start}: docs-test mark followed by no block")
    return sorted(items, key=lambda it: it.line)


def normalise(line):
    line = re.sub(r"\s+", " ", line.strip())
    return line


def line_pattern(expected):
    parts = re.split(r"(\.\.\.|\d+(?:\.\d+)? m?s\b|\d+ cores?\b)", normalise(expected))
    out = []
    for p in parts:
        if p == "...":
            out.append(".*")
        elif re.fullmatch(r"\d+(?:\.\d+)? m?s", p):
            out.append(r"[0-9.]+ m?s")
        elif re.fullmatch(r"\d+ cores?", p):
            out.append(r"\d+ cores?")
        else:
            out.append(re.escape(p))
    return re.compile("^" + "".join(out) + "$")


def compare_output(expected, actual):
    """Expected lines appear in order in the actual output; returns the first one missing."""
    got = [normalise(l) for l in actual.split("\n")]
    pos = 0
    for exp in expected.split("\n"):
        if not exp.strip():
            continue
        if normalise(exp) == "...":
            continue
        pat = line_pattern(exp)
        while pos < len(got) and not pat.match(got[pos]):
            pos += 1
        if pos == len(got):
            return exp
        pos += 1
    return None
