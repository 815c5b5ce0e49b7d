#!/usr/bin/env python3
"""ctest course_zip_safety: hostile zips are refused with one line and exit 2, nothing written
outside the private folder: an entry leaving the folder (".." and absolute), a link, a zip bomb
(an entry that inflates past the bound, whatever its header says), too many entries, not a zip.
usage: test_zip_safety.py SHADOWLAB REPO WORKDIR"""
import os, shutil, stat, subprocess, sys, zipfile

exe, repo, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
lab = os.path.join(repo, "assignments/lab4.json")
good = open(os.path.join(repo, "shaders_core/rgb/lit.frag")).read()


def make(name, fill):
    path = os.path.join(work, name + ".zip")
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as z:
        fill(z)
    return path


def link(z):
    info = zipfile.ZipInfo("rgb/lit.frag")
    info.external_attr = (stat.S_IFLNK | 0o777) << 16
    z.writestr(info, "/etc/passwd")


cases = {
    "dotdot": (lambda z: z.writestr("../../escaped.frag", good), "leaves the folder"),
    "absolute": (lambda z: z.writestr("/tmp/sl-absolute-escape.frag", good), "not a plain relative path"),
    "link": (link, "is a link"),
    "bomb": (lambda z: z.writestr("rgb/lit.frag", "\0" * (200 << 20)), "unpacks to more than"),
    "many": (lambda z: [z.writestr("f%d.txt" % k, "x") for k in range(1100)], "more than 1000 entries"),
}
for name, (fill, want) in cases.items():
    path = make(name, fill)
    r = subprocess.run([exe, "check", "--assignment", lab, "--shaders", path], capture_output=True,
                       text=True, timeout=300)
    lines = [l for l in r.stderr.splitlines() if "refused" in l]
    assert r.returncode == 2, (name, r.returncode, r.stderr[-500:])
    assert len(lines) == 1 and want in lines[0], (name, r.stderr[-500:])
    print("ok:", name, os.path.getsize(path), "bytes:", lines[0])
assert not os.path.exists(os.path.join(work, "..", "escaped.frag"))
assert not os.path.exists("/tmp/sl-absolute-escape.frag")
not_zip = os.path.join(work, "text.zip")
open(not_zip, "w").write("not a zip")
r = subprocess.run([exe, "check", "--assignment", lab, "--shaders", not_zip], capture_output=True, text=True)
assert r.returncode == 2 and "not a zip" in r.stderr, r.stderr
print("course_zip_safety: ok")
