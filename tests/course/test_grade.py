#!/usr/bin/env python3
"""ctest course_grade: a class of mixed folders and zips (wrapper folder, zip in a zip, missing
stages, a broken shader, correct work, the starter, a README only, a zip with a link) graded
with `grade --jobs 2`; every student's points and status are those make_class.py derived from
the assignment; a run killed after its first student resumes and skips it; each student's page
is written by the time the student's line is said, the class's page and gradebook by the last
student's (issue 39: nothing but the class's outputs after it); grades.csv matches the records;
every page loads in headless Chromium with its images decoded and nothing
overflowing.  usage: test_grade.py SHADOWLAB REPO WORKDIR"""
import csv, json, os, queue, re, shutil, signal, subprocess, sys, threading, time

sys.path.insert(0, os.path.dirname(__file__))
import pages

exe, repo, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
lab = os.path.join(repo, "assignments/lab4.json")
subprocess.run([exe, "release", "--assignment", lab, "--out", work + "/release"], check=True,
               stdout=subprocess.DEVNULL)
expected = json.loads(subprocess.run(
    [sys.executable, os.path.join(os.path.dirname(__file__), "make_class.py"), repo,
     work + "/release/shaders", work + "/class"], check=True, capture_output=True, text=True).stdout)
out = work + "/out"


def student_lines(p, seconds, seen):
    """grade's `[student i of n] NAME` lines as they come: (i, n, NAME); every line printed and
    kept in `seen`."""
    lines = queue.Queue()
    threading.Thread(target=lambda: [lines.put(l) for l in p.stdout] + [lines.put("")],
                     daemon=True).start()
    deadline = time.time() + seconds
    while time.time() < deadline:
        try:
            line = lines.get(timeout=max(0.0, deadline - time.time()))
        except queue.Empty:
            break
        if not line:
            return
        print(line, end="")
        seen.append(line)
        m = re.match(r"\[student (\d+) of (\d+)\] (\S+)", line)
        if m:
            yield int(m.group(1)), int(m.group(2)), m.group(3)
    raise AssertionError("grade said nothing for %d s" % seconds)


def page_of(student):
    return out + "/feedback/%s.html" % student


# A run killed once its first student with work to render is said: that student's page is there.
p = subprocess.Popen([exe, "grade", work + "/class", "--assignment", lab, "--out", out, "--jobs", "1", "--time-limit", "300"],
                     stdout=subprocess.PIPE, text=True)
for i, n, student in student_lines(p, 300, []):
    assert os.path.isfile(page_of(student)), "%s said before its page was written" % student
    if student.startswith(("alice", "bob", "carol", "dave")):
        break
p.send_signal(signal.SIGKILL)
p.wait()
first = sorted(os.listdir(out + "/students"))
print("killed after", first)
assert first and len(first) < 6, first
assert not os.path.exists(out + "/class.html")
# ...resumes: the students written are skipped. Each page is written by its student's line, the
# class's page and gradebook by the last line and not before.
p = subprocess.Popen([exe, "grade", work + "/class", "--assignment", lab, "--out", out, "--jobs", "2", "--time-limit", "300"],
                     stdout=subprocess.PIPE, text=True)
said, seen = [], []
for i, n, student in student_lines(p, 900, seen):
    said.append(student)
    assert os.path.isfile(page_of(student)), "%s said before its page was written" % student
    last = len(said) == 6 - len(first)
    for f in ("class.html", "grades.csv", "gradebook-canvas.csv", "gradebook-moodle.csv"):
        assert os.path.isfile(out + "/" + f) == last, "%s %s at %s's line" % (
            f, "missing" if last else "written", student)
assert p.wait(timeout=60) == 0, p.returncode
assert any(l.startswith("graded 6 of 6 in ") for l in seen), "no summary"
assert "%d already graded, %d to grade" % (len(first), 6 - len(first)) in "".join(seen), "no resume"
assert len(said) == 6 - len(first), "graded again what was done: %s" % said

records = {}
for f in os.listdir(out + "/students"):
    j = json.load(open(os.path.join(out, "students", f)))
    records[j["student"]] = j
assert sorted(records) == sorted(expected["points"]), sorted(records)
failures = []
for student, want in expected["points"].items():
    rec = records[student]
    got = {st["stage"]: st["points"] for st in rec["stages"]}
    for stage, pts in want.items():
        if abs(got[stage] - pts) > 0.01:
            failures.append("%s %s: %s points, expected %s" % (student, stage, got[stage], pts))
    if rec["status"] != expected["status"][student]:
        failures.append("%s: status %s, expected %s" % (student, rec["status"], expected["status"][student]))
    # the rows' points add up to the stage's, the stages' to the score
    for st in rec["stages"]:
        assert abs(sum(r["points"] for r in st["rows"]) - st["points"]) < 0.01
        assert abs(sum(r["max_points"] for r in st["rows"]) - st["max_points"]) < 0.01
# the stage-level verdicts the class must show
stage_status = {s: {st["stage"]: st["status"] for st in r["stages"]} for s, r in records.items()}
assert stage_status["bob"]["margin"] == "MISSING" and stage_status["bob"]["rgb"] == "PASS"
assert stage_status["carol"]["depth"] == "ERROR", stage_status["carol"]
assert all(v == "MISSING" for v in stage_status["erin"].values())
assert "link" in records["frank"]["error"], records["frank"]["error"]
assert any("unpacked" in n for n in records["dave"]["notes"]), records["dave"]["notes"]
assert any("bob_lab4" in n for n in records["bob"]["notes"]), records["bob"]["notes"]
assert not failures, "\n".join(failures)

rows = list(csv.DictReader(open(out + "/grades.csv")))
assert len(rows) == 6
for row in rows:
    assert abs(float(row["total"]) - records[row["student"]]["score"]) < 0.01, row
    assert row["status"] == records[row["student"]]["status"]

# Every page in a real browser.
shots = work + "/shots"
os.makedirs(shots)
class_probe = pages.check_page(out + "/class.html", shots + "/class.png")
print("class.html", class_probe)
assert class_probe["broken"] == 0 and class_probe["overflowing"] == 0 and not class_probe["pageWider"]
# Every student's page once in the grade table; the source rules' notes may link a page again.
assert sorted(set(class_probe["links"])) == sorted("feedback/%s.html" % s for s in records), class_probe["links"]
assert class_probe["screenshot"]["colours"] > 3
for student in records:
    page = out + "/feedback/%s.html" % student
    found = pages.check_page(page, shots + "/%s.png" % student)
    print(student, {k: v for k, v in found.items() if k != "links"})
    assert found["broken"] == 0, student + ": an image did not decode"
    assert found["overflowing"] == 0 and not found["pageWider"], student + ": something overflows"
    assert found["screenshot"]["colours"] > 3, student + ": a blank screenshot"
    graded = [st for st in records[student]["stages"] if st["status"] in ("PASS", "FAIL")]
    # one picture set (theirs, truth, diff) per graded stage
    assert found["images"] == 3 * len(graded), (student, found["images"], len(graded))
    assert "data:image/png;base64," in open(page).read() or not graded
print("course_grade: ok")
