#!/usr/bin/env python3
"""`collide grade KEY ANSWERS -o REPORT` end to end. The answers are made here from key.json
(written by `collide worksheet` in the same run) so that each mark follows from the marking
rule |got - want| <= tolerance |want| + 1e-9 and the units' definitions, not from the program:

  right (the value itself), within the tolerance (1 + tol/2), outside it (1 + 2 tol), the sign
  flipped (wrong; named "the sign flipped"), no unit (right, noted), a decimal comma in double
  quotes (right), km/h for m/s (v * 3.6 km/h: right, noted), a true minus, the impulse without
  (1 + e) (wrong; named), a unit of another kind (wrong, noted), a question not answered (0), a
  vector (right, and with ';' and decimal commas), a number for a vector (wrong, noted);

and bad rows: exit 2, one line naming the file, the line and the field, no REPORT written.

Usage: grade.py COLLIDE
"""
import csv
import io
import json
import os
import subprocess
import sys
import tempfile

collide = sys.argv[1]
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)


tmp = tempfile.mkdtemp(prefix="collide-grade-")
env = dict(os.environ, PATH="/nonexistent")


def worksheet(lesson, n):
    d = os.path.join(tmp, lesson)
    r = subprocess.run([collide, "worksheet", lesson, "-o", d, "--students", str(n), "--seed", "11", "--format",
                        "moodle"], capture_output=True, text=True, env=env)
    check(r.returncode == 0, f"worksheet {lesson}: {r.stderr}")
    return os.path.join(d, "key.json"), json.load(open(os.path.join(d, "key.json")))


def grade(key_path, text, report=None):
    ans = os.path.join(tmp, "answers.csv")
    with open(ans, "w", newline="") as f:
        f.write(text)
    args = [collide, "grade", key_path, ans] + (["-o", report] if report else [])
    return subprocess.run(args, capture_output=True, text=True), ans


def comma(x):
    return repr(x).replace(".", ",")


# ---- 1D: catch-up (impulse, two velocities, energy lost) ----
key_path, key = worksheet("catch-up", 12)
students = key["students"]
val = {(s["student"], a["question"]): a for s in students for a in s["answers"]}
# A student whose e is not 1: (1 + e) differs from 2, so "without (1 + e)" is a slip apart from others.
s3 = next(s for s in students[2:] if s["restitution"] < 0.9)["student"]
e3 = next(s for s in students if s["student"] == s3)["restitution"]
v = lambda s, q: val[(s, q)]["value"]
tol = lambda s, q: val[(s, q)]["tolerance"]
rows = [
    # student 1
    (1, 1, f"{v(1, 1)!r} N s", 1, "", ""),
    (1, 2, f"{v(1, 2) * (1 + tol(1, 2) / 2)!r} m/s", 1, "", ""),
    (1, 3, f"{v(1, 3) * (1 + 2 * tol(1, 3))!r} m/s", 0, "", ""),
    (1, 4, f"{v(1, 4)!r}", 1, "no unit: taken as J", ""),
    # student 2
    (2, 1, f"{-v(2, 1)!r} N s", 0, "", "the sign flipped"),
    (2, 2, f"\"{comma(v(2, 2))} m/s\"", 1, "", ""),
    (2, 3, f"{v(2, 3) * 3.6!r} km/h", 1, "km/h converted to m/s", ""),
    # (2, 4): no row -> not answered
    # student s3
    (s3, 1, f"{v(s3, 1) / (1 + e3)!r} N s", 0, "", "without the factor (1 + e)"),
    (s3, 2, f"{v(s3, 2)!r} J", 0, "the unit J is not one of m/s", ""),
    (s3, 3, f"\u2212{-v(s3, 3)!r} m/s" if v(s3, 3) < 0 else f"{v(s3, 3)!r} m/s", 1, "", ""),
    (s3, 4, "", 0, "no answer", ""),
]
text = "student,question,answer\r\n" + "".join(f"{s},{q},{a}\r\n" for s, q, a, *_ in rows)
report = os.path.join(tmp, "report")
r, ans = grade(key_path, text, report)
check(r.returncode == 0, f"grade: exit {r.returncode}: {r.stderr}")
check(sorted(os.listdir(report)) == ["marks.csv", "report.html"], f"report files: {os.listdir(report)}")
marks = {(int(m["student"]), int(m["question"])): m for m in csv.DictReader(open(os.path.join(report, "marks.csv")))}
for s, q, a, mark, note, slip in rows:
    m = marks.get((s, q))
    check(m is not None, f"({s}, {q}) in marks.csv")
    if m:
        check(int(m["mark"]) == mark, f"({s}, {q}) {a!r}: mark {m['mark']}, expected {mark}")
        check(m["note"] == note, f"({s}, {q}): note {m['note']!r}, expected {note!r}")
        check(m["slip"] == slip, f"({s}, {q}): slip {m['slip']!r}, expected {slip!r}")
check(marks.get((2, 4), {}).get("note") == "no answer" and marks[(2, 4)]["mark"] == "0", "(2, 4) not answered")
# Only the students the CSV names, every numeric question of each.
check(sorted({s for s, _ in marks}) == sorted({1, 2, s3}), f"students marked: {sorted({s for s, _ in marks})}")
check(len(marks) == 3 * 4, f"{len(marks)} marks, expected 12")
# The key's other students are said to be left out, not passed over in silence.
absent = sorted(s["student"] for s in students if s["student"] not in {1, 2, s3})
check(len(absent) > 0, "the key has students the answers do not name")
said = "Not marked: the key's student" + ("s " if len(absent) > 1 else " ") + ", ".join(map(str, absent))
check(said + ", with no row in the answers." in r.stdout, f"stdout names the unmarked: {said!r} in {r.stdout!r}")
# The table: student 1 has 3 of 4.
check(any(line.split()[:1] == ["1"] and line.split()[-1] == "3/4" for line in r.stdout.splitlines()),
      f"student 1: 3/4 in\n{r.stdout}")
html = open(os.path.join(report, "report.html")).read()
check(html.count("<svg") == 4, "a histogram per question")
# The questions in the key's words (key.json's "text"), in the tables and the report; the
# CSV's columns as they were (a public format).
for a in students[0]["answers"]:
    check(a["text"].endswith("?"), f"question {a['question']}: words {a['text']!r} in key.json")
    check(f"Q{a['question']}  {a['text']} ({a['unit']})\n" in r.stdout, f"question {a['question']} in words on stdout")
    if "_" not in a["text"]:
        words = a["text"].replace('"', "&quot;")
        check(f"Question {a['question']}: {words}</h3>" in html,
              f"question {a['question']} in words in the report")
check(open(os.path.join(report, "marks.csv")).readline() ==
      "student,question,quantity,answer,value,unit,right_value,mark,note,slip\n", "marks.csv's columns")
# A key written before key.json had the words: the quantity names the question.
old_key = json.load(open(key_path))
for st in old_key["students"]:
    for a in st["answers"]:
        del a["text"]
old_path = os.path.join(tmp, "old-key.json")
json.dump(old_key, open(old_path, "w"))
r_old, _ = grade(old_path, text)
check(r_old.returncode == 0 and f"Q1  {students[0]['answers'][0]['quantity']} (" in r_old.stdout,
      f"an older key: {r_old.returncode} {r_old.stdout!r}")
old_key["students"][0]["answers"][0]["text"] = 3
json.dump(old_key, open(old_path, "w"))
r_bad, _ = grade(old_path, text)
check(r_bad.returncode == 2 and "students[0].answers[0].text" in r_bad.stderr and "expected a string" in r_bad.stderr,
      f"a text that is not a string: {r_bad.returncode} {r_bad.stderr!r}")
check("the sign flipped" in html and "without the factor (1 + e)" in html, "the slips named in the report")

# ---- 2D vectors: general-2d (question 1 the impulse, a vector) ----
key_path, key = worksheet("general-2d", 3)
s = key["students"][0]
a = next(x for x in s["answers"] if isinstance(x["value"], list))
q, (x, y) = a["question"], a["value"]
rows = [(1, q, f"\"({x!r}, {y!r}) {a['unit']}\"", 1, ""),
        (2, q, None, 0, "a vector of 2 components is asked"),
        (3, q, None, 1, "")]
s2, s3v = key["students"][1], key["students"][2]
a2 = next(t for t in s2["answers"] if t["question"] == q)
a3 = next(t for t in s3v["answers"] if t["question"] == q)
rows[1] = (2, q, f"{a2['value'][0]!r} {a['unit']}", 0, "a vector of 2 components is asked")
rows[2] = (3, q, f"\"({comma(a3['value'][0])}; {comma(a3['value'][1])})\"", 1, "no unit: taken as " + a["unit"])
text = "".join(f"{st},{qq},{aa}\n" for st, qq, aa, *_ in rows)
report = os.path.join(tmp, "report2")
r, ans = grade(key_path, text, report)
check(r.returncode == 0, f"grade 2D: {r.stderr}")
if r.returncode == 0:
    marks = {(int(m["student"]), int(m["question"])): m for m in csv.DictReader(open(os.path.join(report, "marks.csv")))}
    for st, qq, aa, mark, note in rows:
        m = marks[(st, qq)]
        check(int(m["mark"]) == mark and m["note"] == note, f"2D ({st}, {qq}) {aa}: {m['mark']} {m['note']!r}")

# ---- Bad rows: exit 2, FILE:LINE: field: message, nothing written ----
key_path = os.path.join(tmp, "catch-up", "key.json")
bad = [
    ("1,1,1,25 m/s\n", 1, "", "expected 3 fields"),
    ("student,question,answer\n1,1,2\n99,1,2\n", 3, "student", "student 99 is not in"),
    ("1,9,2\n", 1, "question", "question 9 is not a numeric question"),
    ("1,1,2\n1,2,about 3\n", 2, "answer", "'about 3' is not a number"),
    ("1,1,2 furlongs\n", 1, "answer", "unit 'furlongs' is not known"),
    ("1,1,2\n1,1,3\n", 2, "", "answered twice (first on line 1)"),
    ("1,1,\"2\n", 1, "", "never closed"),
]
for text, line, field, msg in bad:
    report = os.path.join(tmp, "bad-report")
    r, ans = grade(key_path, text, report)
    where = f"{ans}:{line}: " + (f"{field}: " if field else "")
    check(r.returncode == 2, f"{text!r}: exit {r.returncode}")
    check(r.stderr.startswith("collide: error: " + where) and msg in r.stderr and r.stderr.count("\n") == 1,
          f"{text!r}: stderr {r.stderr!r}, expected {where}...{msg}")
    check(r.stdout == "", f"{text!r}: nothing on stdout")
    check(not os.path.exists(report), f"{text!r}: no report written")

# A file with no answer (the header alone) is refused, not a class of nobody.
r, ans = grade(key_path, "student,question,answer\n", os.path.join(tmp, "bad-report"))
check(r.returncode == 2 and r.stderr == f"collide: error: {ans}: no answers: expected rows of student,question,answer\n"
      and not os.path.exists(os.path.join(tmp, "bad-report")), f"no answers: {r.stderr!r}")

subprocess.run(["rm", "-rf", tmp])
for f in failures:
    print("FAIL:", f)
print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
