#!/usr/bin/env python3
r"""Docs as tests: run the commands a markdown page shows and compare what it says they print.

usage: run_docs.py --exe BUILD/shadowlab --repo ROOT [--long | --all] [--list] PAGE.md

What is tested (docs/README: "The documentation is tested"):
- every fenced block tagged sh, bash or console, and every untagged block whose first line starts
  with "$ ": run in a fresh temporary folder (bash -e -o pipefail: every command must succeed),
  must exit 0 unless a mark says otherwise; a "$ CMD" block's following lines are its expected
  output. The folder links the repository's files (docs/ is a copy: a command may write figures
  there), build/shadowlab is the binary under test and on PATH as `shadowlab`;
- every inline `shadowlab ...` span of the prose: its subcommand must exist and every --option it
  names must be one that `shadowlab SUB --help` lists (a synopsis cannot name a removed option);
- marks, HTML comments invisible when rendered, right before a block or a statement:
    <!-- docs-test: exit: 1; expect: REGEX; long -->          for the next block
    <!-- docs-test: skip: REASON -->                           the next block is not run (printed)
    <!-- docs-test: root: REASON -->                           run as root only, else a skip
    <!-- docs-test: synopsis -->                               the next block is a synopsis
    <!-- docs-test: output -->          the next block is the output of the nearest command above
    <!-- docs-test: file: NAME; run: CMD -->                   the next block is saved as NAME, CMD run
    <!-- docs-test: setup: CMD -->                             run before the block (same folder)
    <!-- docs-test: after: CMD -->                             run after it there, must exit 0
    <!-- docs-test: replace: OLD => NEW -->                    a placeholder of the text made concrete
    <!-- docs-test: text: REGEX; run: CMD; expect: REGEX -->   a statement of the prose: REGEX must
        match within 12 lines of the mark (before or after; "within: N" for more), and {1}, {2}...
        in run and expect are its groups (the number the text states is the number the command must print;
        "\|" in a group reads "|", "..." any text)
  Clauses are separated by new lines or "; " before a key; expect, replace, setup, after repeat.
Output comparison (expected lines in order, others between them allowed) after normalising:
whitespace runs are one space, "..." is any text (a line of only "..." any lines), a time
("50.3 s", "6.6 ms") any number, "N cores" any count, the temporary folder reads ".".
A skip without a reason fails the page, so nothing is skipped silently.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

from doc_page import DEFAULT_TIMEOUT, LONG_TIMEOUT, STATEMENT_WINDOW, compare_output, parse_page


def source_entries(repo):
    """The repository's own top-level files and folders: what git tracks, never a build or what
    an earlier command wrote there (out/, a release, grades/)."""
    try:
        tracked = subprocess.run(["git", "-C", repo, "ls-files", "-z"], check=True,
                                 stdout=subprocess.PIPE, stderr=subprocess.DEVNULL).stdout
        names = {path.split("/")[0] for path in tracked.decode("utf-8", "replace").split("\0") if path}
    except (OSError, subprocess.CalledProcessError):
        names = set(os.listdir(repo))
    return sorted(n for n in names if not n.startswith((".", "build", "out"))
                  and os.path.exists(os.path.join(repo, n)))


class Sandbox:
    """A fresh folder with the repository's data reachable and the binary under test on PATH."""

    def __init__(self, repo, exe):
        self.dir = tempfile.mkdtemp(prefix="docs-test-")
        for name in source_entries(repo):
            src = os.path.join(repo, name)
            if name == "docs":  # commands may write figures into docs/images: a copy, never the repo
                shutil.copytree(src, os.path.join(self.dir, name), symlinks=True)
            else:
                os.symlink(src, os.path.join(self.dir, name))
        os.makedirs(os.path.join(self.dir, "build"))
        os.symlink(exe, os.path.join(self.dir, "build", "shadowlab"))
        self.env = dict(os.environ)
        self.env["PATH"] = os.path.join(self.dir, "build") + os.pathsep + self.env.get("PATH", "")

    def run(self, command, timeout):
        t0 = time.monotonic()
        try:
            # -e: every command of a block must succeed, not only its last
            p = subprocess.run(["bash", "-e", "-o", "pipefail", "-c", command], cwd=self.dir, env=self.env, timeout=timeout,
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
            out, rc = p.stdout.decode("utf-8", "replace"), p.returncode
        except subprocess.TimeoutExpired as e:
            out, rc = (e.stdout or b"").decode("utf-8", "replace") + f"\n[timed out after {timeout} s]", 124
        return rc, out.replace(self.dir + "/", "").replace(self.dir, "."), time.monotonic() - t0

    def close(self):
        shutil.rmtree(self.dir, ignore_errors=True)


def block_commands(item):
    """The shell text a block runs, and the output a "$ " transcript states."""
    if item.text.startswith("$ "):
        lines = item.text.split("\n")
        return lines[0][2:], "\n".join(lines[1:])
    return item.text, item.mark.get("output_text")


class HelpCache:
    def __init__(self, sandbox):
        self.sandbox, self.cache = sandbox, {}

    def options(self, sub):
        if sub not in self.cache:
            rc, out, _ = self.sandbox.run(f"shadowlab {sub} --help", 60)
            self.cache[sub] = (rc, set(re.findall(r"--[a-z][a-z0-9-]*", out)))
        return self.cache[sub]


def check_synopsis(span, helps):
    words = span.split()
    if words[0].endswith("shadowlab"):
        words = words[1:]
    if not words or words[0].startswith("-"):
        return None
    sub = words[0]
    rc, known = helps.options(sub)
    if rc != 0:
        return f"'shadowlab {sub} --help' exits {rc}: no such subcommand?"
    named = set(re.findall(r"(?<![\w-])--[a-z][a-z0-9-]*", span)) - {"--help"}
    unknown = sorted(named - known)
    if unknown:
        return f"'shadowlab {sub}' has no option {', '.join(unknown)} (its --help lists the options)"
    return None


def run_item(item, sandbox_factory, helps, wanted):
    """Returns (status, message, seconds); status PASS, FAIL, SKIP or None (not in this run)."""
    mark = item.mark or {}
    is_long = "long" in mark.get("flags", ())
    if item.kind == "inline":
        if wanted == "long":
            return None, "", 0
        problem = check_synopsis(item.text, helps)
        return ("FAIL", problem, 0) if problem else ("PASS", f"synopsis `{item.text}`", 0)
    if "skip" in mark:
        if wanted == "long" and not is_long:
            return None, "", 0
        if not mark["skip"]:
            return "FAIL", "a skip mark without a reason", 0
        return "SKIP", mark["skip"], 0
    if wanted == "long" and not is_long or wanted == "short" and is_long:
        return None, "", 0
    if "root" in mark and os.geteuid() != 0:
        return "SKIP", f"needs root (CI runs as root): {mark['root']}", 0
    if "synopsis" in mark["flags"]:
        # one command per line starting "shadowlab SUB"; an indented line continues it
        commands = []
        for line in item.text.split("\n"):
            if re.match(r"(\./build/)?shadowlab ", line):
                commands.append(line)
            elif commands and line.startswith(" ") and line.strip().startswith(("[", "-")):
                commands[-1] += " " + line.strip()
        if not commands:
            return "FAIL", "a synopsis mark on a block with no 'shadowlab SUB' line", 0
        for command in commands:
            problem = check_synopsis(command.split("(the")[0], helps)
            if problem:
                return "FAIL", problem, 0
        return "PASS", f"synopsis of {len(commands)} commands", 0
    if item.kind == "statement":
        groups = ()
        if "text" in mark:
            m = re.search(mark["text"], item.text)
            if not m:
                within = mark.get("within", STATEMENT_WINDOW)
                return "FAIL", f"the statement /{mark['text']}/ is not within {within} lines of its mark", 0
            # a table cell escapes "|" as "\|"; "..." in the text leaves a part out
            groups = [g.replace("\\|", "|") for g in m.groups()]
            # the line of the first number or phrase captured (the statement itself)
            where = m.start(1) if m.lastindex and m.start(1) >= 0 else m.start()
            item.stated_at = item.first_line + item.text.count("\n", 0, where)
        command, expected_output = mark.get("run"), mark.get("output_text")
        for n, g in enumerate(groups, 1):  # "run: shadowlab {1}": the command is the text's own
            command = command.replace("{%d}" % n, g) if command else command
        if not command:
            return "PASS", "statement found", 0
    else:
        command, expected_output = block_commands(item)
        if "run" in mark:  # the block is a file, run by the mark's command
            command = f"cat > {mark['file']} <<'DOCS_TEST_EOF'\n{item.text}\nDOCS_TEST_EOF\n{mark['run']}"
        groups = ()
    for old, new in mark["replace"]:
        if old not in command:
            return "FAIL", f"replace: '{old}' is not in the command any more", 0
        command = command.replace(old, new)
    sandbox = sandbox_factory()
    try:
        for setup in mark["setup"]:
            rc, out, _ = sandbox.run(setup, DEFAULT_TIMEOUT)
            if rc != 0:
                return "FAIL", f"setup '{setup}' exited {rc}:\n{out[-2000:]}", 0
        timeout = int(mark.get("timeout", LONG_TIMEOUT if is_long else DEFAULT_TIMEOUT))
        rc, out, seconds = sandbox.run(command, timeout)
        after_failed = None
        for after in mark["after"]:
            arc, aout, _ = sandbox.run(after, DEFAULT_TIMEOUT)
            if arc != 0 and after_failed is None:
                after_failed = f"after the block, '{after}' exited {arc}:\n{aout[-2000:]}"
    finally:
        sandbox.close()
    want_rc = int(mark.get("exit", 0))
    tail = out[-3000:]
    if rc != want_rc:
        return "FAIL", f"exit {rc}, the text expects {want_rc}; output:\n{tail}", seconds
    if after_failed:
        return "FAIL", after_failed, seconds
    for regex in mark["expect"]:
        for n, g in enumerate(groups, 1):
            regex = regex.replace("{%d}" % n, re.escape(g).replace(re.escape("..."), ".*"))
        if not re.search(regex, out, re.M):
            return "FAIL", f"output does not match /{regex}/; output:\n{tail}", seconds
    if expected_output:
        missing = compare_output(expected_output, out)
        if missing is not None:
            at = mark.get("output_line", 0) + expected_output.split("\n").index(missing)
            return "FAIL", (f"the text shows the line (line {at})\n    {missing.strip()}\n"
                            f"which the output lacks; output:\n{tail}"), seconds
    return "PASS", f"exit {rc}", seconds


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("page")
    ap.add_argument("--exe", required=True)
    ap.add_argument("--repo", required=True)
    group = ap.add_mutually_exclusive_group()
    group.add_argument("--long", action="store_true", help="only the blocks marked long")
    group.add_argument("--all", action="store_true", help="short and long blocks")
    ap.add_argument("--list", action="store_true", help="list the items, run nothing")
    ap.add_argument("--count-long", action="store_true",
                    help="print how many items are marked long (ctest registers docs-long by it)")
    args = ap.parse_args()
    repo, exe = os.path.abspath(args.repo), os.path.abspath(args.exe)
    rel = os.path.relpath(os.path.abspath(args.page), repo)
    try:
        items = parse_page(args.page)
    except ValueError as e:
        print(f"{rel}: {e}")
        return 1
    if args.count_long:
        print(sum(1 for it in items if it.mark and "long" in it.mark["flags"]))
        return 0
    if args.list:
        for it in items:
            print(f"{rel}:{it.line}: {it.kind} {it.text.splitlines()[0] if it.text else ''}")
        return 0
    wanted = "long" if args.long else "all" if args.all else "short"
    help_box = Sandbox(repo, exe)
    helps = HelpCache(help_box)
    counts = {"PASS": 0, "FAIL": 0, "SKIP": 0}
    reasoned_skips = sum(1 for it in items if it.mark and (it.mark.get("skip") or it.mark.get("root")))
    try:
        for it in items:
            status, message, seconds = run_item(it, lambda: Sandbox(repo, exe), helps, wanted)
            if status is None:
                continue
            counts[status] += 1
            shown = it.mark.get("run", "") if it.kind == "statement" else it.text.strip()
            first = shown.splitlines()[0] if shown else ""
            where = f"{rel}:{it.line}"
            if status == "FAIL" and getattr(it, "stated_at", None):
                where = f"{rel}:{it.stated_at} (the statement; its mark at line {it.line})"
            if status == "PASS":
                print(f"ok   {where}: {it.kind} `{first[:70]}`: {message} ({seconds:.1f} s)")
            elif status == "SKIP":
                print(f"skip {where}: {it.kind} `{first[:70]}`: {message}")
            else:
                print(f"FAIL {where}: {it.kind} `{first[:70]}`: {message}")
            sys.stdout.flush()
    finally:
        help_box.close()
    print(f"{rel}: {counts['PASS']} passed, {counts['FAIL']} failed, {counts['SKIP']} skipped "
          f"({reasoned_skips} skip marks with a reason)")
    if counts["SKIP"] > reasoned_skips:
        print(f"FAIL {rel}: {counts['SKIP']} skipped but only {reasoned_skips} skip marks give a reason")
        return 1
    return 1 if counts["FAIL"] else 0


if __name__ == "__main__":
    sys.exit(main())
