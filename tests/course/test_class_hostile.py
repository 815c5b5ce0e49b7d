#!/usr/bin/env python3
"""ctest course_class_hostile: a hostile, careless class folder graded as a grading box does (as
root; the links to /etc and /etc/shadow are made whoever runs it, /etc/shadow's bytes are only
readable as root, so as another user the secret check proves less and says so).
Each case asserts what a careful instructor expects (docs/robustness.md, "A class folder"):
  links (to /etc, /etc/shadow, a folder outside the class, a classmate's zip) are that hand-in
  refused with one line naming it, nothing followed or copied into --out; a FIFO is refused
  without being opened; class-level junk (Thumbs.db, desktop.ini, .DS_Store, __MACOSX) is never
  a student; dot-folders and `~` names are left out and named in the summary and on the class
  page; `zz_same/` and `zz_same.zip` are two rows, two records, two picture folders; a 251-byte
  name is graded (the job does not die); `a b` added after `a_b` was graded is graded alone,
  one row each (resume by exact name); zip entry names are read as UTF-8 under LC_ALL=C
  (`Rapport_été.pdf`, `Screen Shot 10:30.png`, a 300-byte name left out with a note); an
  encrypted zip says so; a nested zip's messages name the student's archive, never our work
  folder; --out inside, equal to or holding the submissions folder is refused before any work;
  release --out inside the data tree is refused; a second grade on a locked --out is refused
  naming the holder's pid; the same zips through `check` under LC_ALL=C; a full disk under --out
  (a tmpfs, as root) makes a folder's and a zip's hand-ins NOT GRADED, saying the disk is full.
usage: test_class_hostile.py SHADOWLAB REPO WORKDIR"""
import csv, fcntl, io, json, os, shutil, subprocess, sys, zipfile

exe, repo, work = os.path.abspath(sys.argv[1]), sys.argv[2], sys.argv[3]
shutil.rmtree(work, ignore_errors=True)
cls, out = work + "/class", work + "/out"
os.makedirs(cls)
lab = work + "/lab.json"
json.dump({"name": "margin only",
           "stages": [{"stage": "margin", "tree": "core", "files": ["margin/lit.frag"], "points": 10,
                       "lessons": {"margin margin-kind=slope": 0},
                       "views": {"cube-on-cube": {"weight": 0}, "sphere-on-cube": {"weight": 0},
                                 "cube-on-sphere": {"weight": 0}, "grazing": {"weight": 0}}}]},
          open(lab, "w"))
shipped = open(os.path.join(repo, "shaders_core/margin/lit.frag"), "rb").read()
SECRET = b"SECRET-KEY-do-not-copy-7f3a"
ENV = dict(os.environ, LC_ALL="C", LANG="C")
checks = []


def check(label, ok, detail=""):
    checks.append(label)
    print(("ok:   " if ok else "FAIL: ") + label + ("" if ok else " -- " + str(detail)[:1500]))
    if not ok:
        sys.exit(1)


def folder(name, files):
    for rel, data in files.items():
        path = os.path.join(cls, name, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        open(path, "wb").write(data)


def zipped(path, files):
    with zipfile.ZipFile(path, "w", zipfile.ZIP_STORED) as z:
        for rel, data in files.items():
            z.writestr(rel, data)


def encrypted(path, files):
    """A zip whose entries carry the 'encrypted' flag (bit 0), as a password-protected one does."""
    zipped(path, files)
    data = bytearray(open(path, "rb").read())
    for sig, flag_at in ((b"PK\x03\x04", 6), (b"PK\x01\x02", 8)):
        at = data.find(sig)
        while at >= 0:
            data[at + flag_at] |= 1
            at = data.find(sig, at + 4)
    open(path, "wb").write(bytes(data))


def grade(*extra, code=0, subs=cls, dest=out):
    r = subprocess.run([exe, "grade", subs, "--assignment", lab, "--out", dest, "--seed", "4242",
                        "--time-limit", "300"] + list(extra), capture_output=True, text=True,
                       timeout=1200, env=ENV)
    print("$ grade", subs, "--out", dest, *extra, "->", r.returncode)
    print(r.stdout[-3000:], r.stderr[-2000:])
    return r


def every_output_text():
    """Every file under --out, as bytes, with its path (what a student or instructor may see)."""
    for root, dirs, files in os.walk(out):
        for f in files:
            p = os.path.join(root, f)
            if not os.path.islink(p):
                yield p, open(p, "rb").read()


# ---- the class
folder("ann", {"margin/lit.frag": shipped})
folder("a_b", {"margin/lit.frag": shipped})
folder("L" * 251, {"margin/lit.frag": shipped})
folder("zz_same", {"margin/lit.frag": shipped})
zipped(cls + "/zz_same.zip", {"README.txt": b"nothing yet\n"})
zipped(cls + "/utf.zip", {"margin/lit.frag": shipped, "Rapport_\u00e9t\u00e9.pdf": b"%PDF-1.4\n",
                          "Screen Shot 10:30.png": b"\x89PNG\r\n", "x" * 300 + ".txt": b"long\n"})
encrypted(cls + "/locked.zip", {"margin/lit.frag": shipped})
inner = io.BytesIO()
zipped(inner, {"README.txt": b"see the pdf\n"})
zipped(cls + "/nest.zip", {"l2.zip": inner.getvalue()})
os.makedirs(work + "/outside/margin")
open(work + "/outside/margin/lit.frag", "wb").write(shipped)
open(work + "/outside/id_rsa", "wb").write(SECRET)
os.symlink("/etc", cls + "/link_etc")
os.symlink("/etc/shadow", cls + "/link_shadow.zip")
os.symlink(work + "/outside", cls + "/link_outside")
os.symlink("zz_same.zip", cls + "/copy.zip")
os.mkfifo(cls + "/pipe")
for junk in ("Thumbs.db", "desktop.ini", ".DS_Store"):
    open(os.path.join(cls, junk), "wb").write(b"\0junk")
folder("__MACOSX", {"._ann": b"\0"})
folder(".hidden", {"margin/lit.frag": shipped})
folder("name~", {"margin/lit.frag": shipped})

# ---- --out overlapping the class: refused before any work (nothing created)
for dest, want in ((cls + "/grades", "lies inside the submissions folder"),
                   (cls, "is the submissions folder"), (work, "holds the submissions folder"),
                   (cls + "/../class/./sub", "lies inside the submissions folder")):
    r = grade(dest=dest)
    lines = r.stderr.strip().splitlines()
    check("--out %s refused with one line" % dest.replace(work, "WORK"),
          r.returncode == 2 and len(lines) == 1 and want in lines[0], r.stderr)
    check("--out %s: nothing written" % dest.replace(work, "WORK"),
          not os.path.exists(cls + "/grades") and not os.path.exists(cls + "/sub") and
          not os.path.exists(cls + "/students") and not os.path.exists(work + "/students"))

# ---- release --out inside the data tree
for top in ("scenes", "shaders_core/margin", "src"):
    dest = os.path.join(repo, top, "release-test-out")
    r = subprocess.run([exe, "release", "--assignment", lab, "--out", dest, "--gradescope"],
                       capture_output=True, text=True, timeout=300)
    made = os.path.exists(dest)
    shutil.rmtree(dest, ignore_errors=True)
    check("release --out inside %s refused" % top,
          r.returncode == 2 and "what the release is made from" in r.stderr and not made, r.stderr)

# ---- the run
r = grade()
check("first run exits 0", r.returncode == 0, r.stderr)
rows = list(csv.DictReader(open(out + "/grades.csv")))
students = [row["student"] for row in rows]
expected = sorted(["ann", "a_b", "L" * 251, "zz_same", "zz_same.zip", "utf", "locked", "nest",
                   "link_etc", "link_shadow", "link_outside", "copy", "pipe"])
check("one row per hand-in, no junk and no skipped name a student",
      sorted(students) == expected, students)
records = {}
for f in os.listdir(out + "/students"):
    rec = json.load(open(os.path.join(out, "students", f)))
    records[rec["student"]] = (f, rec)
check("one record per hand-in, each under its own file", sorted(records) == expected,
      sorted(records))
check("no record file name longer than 100 bytes",
      all(len(f.encode()) <= 100 for f, _ in records.values()), [f for f, _ in records.values()])
status = {name: rec["status"] for name, (f, rec) in records.items()}
rec_text = {name: json.dumps(rec, ensure_ascii=False) for name, (f, rec) in records.items()}
for name in ("ann", "a_b", "L" * 251, "zz_same", "utf"):
    check("%s graded PASS" % name[:20], status[name] == "PASS", status[name])
check("zz_same.zip (a README) is MISSING, apart from zz_same/",
      status["zz_same.zip"] == "MISSING", status["zz_same.zip"])
pictures = sorted(d for d in os.listdir(out + "/work") if d.startswith("zz_same"))
check("zz_same/ and zz_same.zip: two work (picture) folders", len(pictures) == 2, pictures)
for name, want in (("link_etc", "link_etc: a link"), ("link_shadow", "link_shadow.zip: a link"),
                   ("link_outside", "link_outside: a link"), ("copy", "copy.zip: a link"),
                   ("pipe", "pipe: not a folder or a file")):
    check("%s refused as that hand-in, naming it" % name,
          status[name] == "ERROR" and want in rec_text[name], rec_text[name][:600])
check("encrypted zip says so",
      status["locked"] == "ERROR" and "encrypted: hand it in without a password" in rec_text["locked"],
      rec_text["locked"][:600])
check("nested zip's notes name nest.zip/l2.zip",
      status["nest"] == "MISSING" and "nest.zip/l2.zip" in rec_text["nest"], rec_text["nest"][:800])
check("the long entry name of utf.zip left out with a note",
      "left out: its name is too long" in rec_text["utf"], rec_text["utf"][:800])
etc_names = set(os.listdir("/etc"))
copied = [p for p, _ in every_output_text() if "/work/link" in p or "/work/copy" in p]
check("nothing of a link's target copied into --out/work", copied == [], copied[:5])
leaks = []
shadow = b""
try:
    shadow = open("/etc/shadow", "rb").read().split(b"\n")[0]
except OSError:
    print("note: /etc/shadow is not readable by this user (not root): its bytes are not searched")
passwd = open("/etc/passwd", "rb").read().split(b"\n")[0]
for p, data in every_output_text():
    for secret in (SECRET, passwd, shadow):
        if secret and secret in data:
            leaks.append(p)
for text in (r.stdout, r.stderr):
    if SECRET.decode() in text or passwd.decode() in text:
        leaks.append("stdout/stderr")
check("no secret (id_rsa, /etc/passwd, /etc/shadow) in any output", leaks == [], leaks[:5])
# What people read: pages, the gradebook, the terminal, and the records' messages (the records
# also keep where the pictures and snapshot are, for our own reruns).
shown = [(p, data) for p, data in every_output_text()
         if "/feedback/" in p or p.endswith(("class.html", "grades.csv"))]
shown += [("stdout", r.stdout.encode()), ("stderr", r.stderr.encode())]
shown += [(name, json.dumps([rec.get("notes"), rec.get("message"),
                             [st.get("message") for st in rec["stages"]]]).encode())
          for name, (f, rec) in records.items()]
ours = [b"/unpacked", (out + "/work/").encode(), (os.path.abspath(out) + "/work/").encode()]
internal = [p for p, data in shown if any(o in data for o in ours)]
check("no page, gradebook, terminal line or message names our work folders", internal == [],
      internal[:5])
summary = [l for l in r.stdout.splitlines() if l.startswith("left out, not hand-ins:")]
page = open(out + "/class.html", encoding="utf-8").read()
for name in (".hidden", "name~", "Thumbs.db", "desktop.ini", ".DS_Store", "__MACOSX"):
    check("%s named in the summary and on the class page" % name,
          len(summary) == 1 and name in summary[0] and name in page, summary)

# ---- resume by exact name: `a b` added after `a_b` was graded
folder("a b", {"margin/lit.frag": shipped})
r = grade()
check("rerun exits 0", r.returncode == 0, r.stderr)
check("rerun grades `a b` alone", "1 to grade (1 new)" in r.stdout and
      r.stdout.count("[student ") == 1 and "a b " in r.stdout, r.stdout)
students = [row["student"] for row in csv.DictReader(open(out + "/grades.csv"))]
check("one row for a_b and one for `a b`",
      students.count("a_b") == 1 and students.count("a b") == 1 and
      len(students) == len(expected) + 1, students)

# ---- a second grade on a locked --out
holder = open(out + "/.grade.lock", "r+")
fcntl.flock(holder, fcntl.LOCK_EX)
holder.seek(0)
holder.truncate()
holder.write("%d\n" % os.getpid())
holder.flush()
r = grade()
fcntl.flock(holder, fcntl.LOCK_UN)
holder.close()
check("a locked --out is refused naming the holder's pid",
      r.returncode == 2 and "in use by another grade run (pid %d)" % os.getpid() in r.stderr, r.stderr)
# ---- the same zips through `check` (and so run_autograder), under LC_ALL=C
for zip_name, code, want in (("utf.zip", 0, "total: 10 of 10 points"),
                             ("locked.zip", 2, "encrypted: hand it in without a password"),
                             ("nest.zip", 2, "nest.zip/l2.zip: no file replaces")):
    r = subprocess.run([exe, "check", "--assignment", lab, "--shaders", os.path.join(cls, zip_name)],
                       capture_output=True, text=True, timeout=300, env=ENV)
    check("check %s under LC_ALL=C: exit %d, '%s'" % (zip_name, code, want),
          r.returncode == code and want in r.stdout + r.stderr and "unpacked-inner" not in r.stderr,
          (r.returncode, r.stdout[-500:], r.stderr[-500:]))
# ---- a full disk under --out (a tmpfs of 256 KiB; root only): NOT GRADED, never a score
if os.geteuid() != 0:
    print("skipped: the full-disk case needs root (mount -t tmpfs); CI runs as root")
else:
    full_cls, mnt = work + "/full-class", work + "/full"
    big = shipped + b"\n// " + b"x" * (900 << 10) + b"\n"  # under the 1 MiB bound, over the disk
    os.makedirs(full_cls + "/bigdir/margin")
    open(full_cls + "/bigdir/margin/lit.frag", "wb").write(big)
    with zipfile.ZipFile(full_cls + "/bigzip.zip", "w", zipfile.ZIP_DEFLATED) as z:
        z.writestr("margin/lit.frag", big)
    os.makedirs(mnt)
    subprocess.run(["mount", "-t", "tmpfs", "-o", "size=256k", "tmpfs", mnt], check=True)
    try:
        r = grade(subs=full_cls, dest=mnt + "/out")
        check("a full disk: exit 3, 'not graded: rerun'",
              r.returncode == 3 and "2 not graded: rerun" in r.stdout, (r.returncode, r.stdout))
        rows = {row["student"]: row for row in csv.DictReader(open(mnt + "/out/grades.csv"))}
        for name in ("bigdir", "bigzip"):
            rec = json.load(open(mnt + "/out/students/%s.json" % name))
            check("a full disk: %s NOT GRADED, no score, 'the disk is full'" % name,
                  rec["status"] == "NOT GRADED" and rec["max_score"] == 0 and
                  rows[name]["total"] == "" and "disk is full" in rows[name]["not_graded"] and
                  "not the submission's fault" in rows[name]["not_graded"],
                  (rec["status"], rows.get(name)))
    finally:
        subprocess.run(["umount", mnt])
print("course_class_hostile: ok, %d checks" % len(checks))
