#!/usr/bin/env python3
"""Fetches Debian's source packages of glslang and SPIRV-Cross, the versions installed here,
and unpacks them for the browser edition (cmake/web.cmake compiles them to WebAssembly), so the
page accepts GLSL by the same glslang as `shadowlab check`. The sources come from the system's
own Debian archive (its `deb` lines read as `deb-src`, in a private apt state: the system's
sources and lists are not touched). Nothing is fetched when the folder already holds them.

usage: web_sources.py OUT_DIR      prints the two unpacked folders, one a line
"""
import pathlib
import re
import subprocess
import sys
import tempfile

# source package -> the binary package whose installed version the page must equal
PACKAGES = {"glslang": "glslang-dev", "spirv-cross": "spirv-cross"}


def fail(message):
    sys.exit(f"web_sources: {message}")


def installed_version(binary):
    run = subprocess.run(["dpkg-query", "-W", "-f=${Version}", binary], capture_output=True,
                         text=True)
    if run.returncode != 0 or not run.stdout:
        fail(f"{binary} is not installed (scripts/deps.sh --web)")
    return run.stdout


def source_lines():
    """The system's `deb` entries as `deb-src` (one-line and deb822 forms)."""
    etc = pathlib.Path("/etc/apt")
    one_line, stanzas = [], []
    for path in [etc / "sources.list", *sorted((etc / "sources.list.d").glob("*.list"))]:
        if path.is_file():
            for line in path.read_text().splitlines():
                if re.match(r"^\s*deb\s", line):
                    one_line.append(re.sub(r"^\s*deb\s", "deb-src ", line))
    for path in sorted((etc / "sources.list.d").glob("*.sources")):
        for stanza in re.split(r"\n\s*\n", path.read_text()):
            if re.search(r"^Types:.*\bdeb\b", stanza, re.M):
                stanzas.append(re.sub(r"^Types:.*$", "Types: deb-src", stanza.strip(), flags=re.M))
    return "\n".join(one_line) + "\n", "\n\n".join(stanzas) + "\n"


def fetch(out, wanted):
    with tempfile.TemporaryDirectory() as tmp:
        state = pathlib.Path(tmp)
        (state / "lists/partial").mkdir(parents=True)
        (state / "cache/archives/partial").mkdir(parents=True)
        (state / "parts").mkdir()
        one_line, deb822 = source_lines()
        (state / "sources.list").write_text(one_line)
        (state / "parts/system.sources").write_text(deb822)
        apt = ["apt-get", "-q", "-o", f"Dir::Etc::sourcelist={state}/sources.list",
               "-o", f"Dir::Etc::sourceparts={state}/parts", "-o", f"Dir::State::Lists={state}/lists",
               "-o", f"Dir::Cache={state}/cache", "-o", "Debug::NoLocking=1"]
        for args in (["update"], ["source", "--download-only", *wanted]):
            run = subprocess.run(apt + args, cwd=out, capture_output=True, text=True)
            if run.returncode != 0:
                fail(f"apt-get {args[0]} failed:\n{run.stdout}{run.stderr}")


def main():
    if len(sys.argv) != 2:
        fail("usage: web_sources.py OUT_DIR")
    out = pathlib.Path(sys.argv[1]).resolve()
    out.mkdir(parents=True, exist_ok=True)
    folders, wanted = {}, []
    for source, binary in PACKAGES.items():
        version = installed_version(binary)
        upstream = re.sub(r"^\d+:", "", version)
        folders[source] = out / f"{source}-{upstream}"
        if not (folders[source] / "CMakeLists.txt").is_file():
            wanted.append(f"{source}={version}")
    if wanted:
        print(f"web_sources: fetching {' '.join(wanted)} from Debian's archive", file=sys.stderr)
        fetch(out, wanted)
        for source, folder in folders.items():
            dsc = sorted(out.glob(f"{source}_*.dsc"))
            if not (folder / "CMakeLists.txt").is_file():
                if not dsc:
                    fail(f"no {source} .dsc was fetched into {out}")
                subprocess.run(["dpkg-source", "--no-check", "-x", str(dsc[-1]), str(folder)],
                               check=True, capture_output=True)
    for folder in folders.values():
        print(folder)


if __name__ == "__main__":
    main()
