#!/usr/bin/env python3
"""Writes a class of realistic submissions for the lab4 assignment into DEST, and prints the
points each student must get (JSON) from what each one handed in, decided here from the
assignment, not from any grading run:
  alice      folder, every stage correct (the shipped solutions)          -> full points
  bob.zip    zip with a wrapper folder, rgb and depth only (correct)       -> rgb + depth, others MISSING
  carol      folder, depth's lit.frag does not compile, the rest correct  -> all but depth (ERROR)
  dave.zip   a zip holding a zip of the starter release (stubs)           -> 0, every stage graded FAIL
  erin       a README only                                                -> 0, every stage MISSING
  frank.zip  a zip with a symbolic link in it                             -> refused: 0, ERROR
usage: make_class.py REPO RELEASE_SHADERS DEST
"""
import io, json, os, shutil, stat, sys, zipfile

repo, release, dest = sys.argv[1:4]
lab = json.load(open(os.path.join(repo, "assignments/lab4.json")))
due = [s for s in lab["stages"] if s.get("due", True)]
core = os.path.join(repo, "shaders_core")


def put(root, rel, text):
    path = os.path.join(root, rel)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


def shipped(rel):
    return open(os.path.join(core, rel)).read()


os.makedirs(dest)
points = {}
# alice: every due file, correct
for s in due:
    for f in s["files"]:
        put(os.path.join(dest, "alice"), f, shipped(f))
points["alice"] = {s["stage"]: s["points"] for s in due}
# bob: a zip of bob_lab4/{rgb,depth}
buf = io.BytesIO()
with zipfile.ZipFile(buf, "w") as z:
    for s in due[:2]:
        for f in s["files"]:
            z.writestr("bob_lab4/" + f, shipped(f))
    z.writestr("__MACOSX/bob_lab4/._rgb", "junk")
open(os.path.join(dest, "bob.zip"), "wb").write(buf.getvalue())
points["bob"] = {s["stage"]: (s["points"] if i < 2 else 0) for i, s in enumerate(due)}
# carol: depth broken
for s in due:
    for f in s["files"]:
        text = shipped(f)
        if s["stage"] == "depth":
            text = text.replace("float visibility = 1.0;", "float visibility = 1.0")  # missing ;
        put(os.path.join(dest, "carol"), f, text)
points["carol"] = {s["stage"]: (0 if s["stage"] == "depth" else s["points"]) for s in due}
# dave: a zip inside a zip, holding the starter release's files
inner = io.BytesIO()
with zipfile.ZipFile(inner, "w") as z:
    for s in due:
        for f in s["files"]:
            z.writestr(f, open(os.path.join(release, f)).read())
outer = io.BytesIO()
with zipfile.ZipFile(outer, "w") as z:
    z.writestr("submission.zip", inner.getvalue())
open(os.path.join(dest, "dave.zip"), "wb").write(outer.getvalue())
points["dave"] = {s["stage"]: 0 for s in due}
# erin: nothing but a README
put(os.path.join(dest, "erin"), "README.txt", "I could not finish, sorry\n")
points["erin"] = {s["stage"]: 0 for s in due}
# frank: a symlink entry
buf = io.BytesIO()
with zipfile.ZipFile(buf, "w") as z:
    z.writestr(due[0]["files"][0], shipped(due[0]["files"][0]))
    link = zipfile.ZipInfo("depth/lit.frag")
    link.external_attr = (stat.S_IFLNK | 0o777) << 16
    z.writestr(link, "/etc/passwd")
open(os.path.join(dest, "frank.zip"), "wb").write(buf.getvalue())
points["frank"] = {s["stage"]: 0 for s in due}
# A student's status is their worst stage's (grade/status.h): PASS < FAIL < MISSING < ERROR.
status = {"alice": "PASS", "bob": "MISSING", "carol": "ERROR", "dave": "FAIL",
          "erin": "MISSING", "frank": "ERROR"}
json.dump({"points": points, "status": status}, sys.stdout, indent=1)
