#!/usr/bin/env python3
"""`collide worksheet --format moodle`: DIR/moodle.xml read with a real XML parser (xml.etree)
and every question checked against key.json, written by the same run:

- one category per lesson, under it one category per question of the sheet holding exactly
  one question per student (a quiz's "random question" draws a variant from it);
- numerical: the answer is key.json's value (17 digits: exact), the absolute tolerance is
  tolerance |value| + 1e-9 (the marking rule, teach/answers.h), the unit is key.json's with
  multiplier 1 and every other accepted unit's multiplier is its definition (km/h: 3.6,
  kJ: 0.001, rpm: 60 / 2 pi);
- cloze (vectors): one NUMERICAL field per component, each key.json's component, with
  tolerance (tolerance |v| + 1e-9) / sqrt(components);
- multichoice: fraction 100 on exactly one option, every option with feedback; essay: grader
  information; every question text names the student and holds the givens; a 2D lesson's
  question holds its figure as an @@PLUGINFILE@@ file that parses as SVG;
- --format refusals: exit 2, one line naming --format, no directory.

Usage: moodle_xml.py COLLIDE
"""
import base64
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

collide = sys.argv[1]
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)


# Definitions, not the program's table: value in the unit = value in base * multiplier.
MULTIPLIERS = {("m/s", "km/h"): 3.6, ("J", "kJ"): 1e-3, ("rad/s", "rpm"): 60 / (2 * math.pi),
               ("m/s", "cm/s"): 100.0, ("rad/s", "deg/s"): 180 / math.pi}

LESSONS = ["catch-up", "general-2d", "rotation-directions", "general-3d"]  # 1D, 2D vectors + essay, choices, 3D
STUDENTS = 4

tmp = tempfile.mkdtemp(prefix="collide-moodle-")
out = os.path.join(tmp, "ws")
env = dict(os.environ, PATH="/nonexistent")  # no weasyprint: no PDFs
run = subprocess.run([collide, "worksheet", *LESSONS, "-o", out, "--students", str(STUDENTS), "--seed", "5",
                      "--format", "html,moodle"], capture_output=True, text=True, env=env)
check(run.returncode == 0, f"worksheet exit {run.returncode}: {run.stderr}")
check("moodle.xml" in run.stdout, f"summary names moodle.xml: {run.stdout}")

root = ET.parse(os.path.join(out, "moodle.xml")).getroot()
check(root.tag == "quiz", "root is <quiz>")

# The questions under each category path.
by_category = {}
category = None
for q in root:
    if q.get("type") == "category":
        category = q.find("category/text").text
        check(category not in by_category, f"category {category} once")
        by_category[category] = []
    else:
        check(category is not None, "a question before any category")
        by_category[category].append(q)

for lesson in LESSONS:
    key = json.load(open(os.path.join(out, lesson, "key.json")))
    cats = {c: qs for c, qs in by_category.items() if c.startswith("$course$/top/Collide worksheets/") and
            re.search(r"\(" + re.escape(lesson) + r"\)(/|$)", c)}
    top = [c for c in cats if c.endswith("(" + lesson + ")")]
    check(len(top) == 1 and cats[top[0]] == [], f"{lesson}: one empty lesson category, got {top}")
    question_cats = {c: qs for c, qs in cats.items() if "/Question " in c}
    numbers = sorted(int(c.rsplit(" ", 1)[1]) for c in question_cats)
    key_numbers = [a["question"] for a in key["students"][0]["answers"]]
    check(set(key_numbers) <= set(numbers), f"{lesson}: every numeric question of the key has a category")
    for c, qs in question_cats.items():
        n = int(c.rsplit(" ", 1)[1])
        check(len(qs) == STUDENTS, f"{c}: {len(qs)} variants, expected {STUDENTS}")
        types = {q.get("type") for q in qs}
        check(len(types) == 1, f"{c}: one type of question, got {types}")
        for q, s in zip(qs, key["students"]):
            name = q.find("name/text").text
            check(name.endswith("student %03d" % s["student"]), f"{c}: variant {name} in student order")
            text = q.find("questiontext/text").text
            check(f"Student {s['student']}" in text, f"{name}: names the student")
            check("<table class=\"givens\">" in text, f"{name}: holds the givens")
            check(q.find("generalfeedback/text").text is not None and "worked out" in
                  q.find("generalfeedback/text").text, f"{name}: the worked example as general feedback")
            # The figure (2D): a file of the question, referenced, parsing as SVG.
            files = q.findall("questiontext/file")
            if lesson in ("general-2d", "rotation-directions"):
                check(len(files) == 1, f"{name}: one figure file")
                for f in files:
                    check(f"@@PLUGINFILE@@/{f.get('name')}" in text, f"{name}: the figure is shown")
                    svg = ET.fromstring(base64.b64decode(f.text))
                    check(svg.tag == "{http://www.w3.org/2000/svg}svg", f"{name}: the file is SVG")
            else:
                check(not files, f"{name}: no figure in 1D and 3D")
            answers = [a for a in s["answers"] if a["question"] == n]
            kind = q.get("type")
            if answers:
                a = answers[0]
                if isinstance(a["value"], list):
                    check(kind == "cloze", f"{name}: a vector is a cloze")
                    fields = re.findall(r"\{1:NUMERICAL:=([^:}]+):([^}]+)\}", text)
                    check(len(fields) == len(a["value"]), f"{name}: {len(fields)} fields for {a['value']}")
                    size = math.sqrt(sum(x * x for x in a["value"]))
                    each = (a["tolerance"] * size + 1e-9) / math.sqrt(len(a["value"]))
                    for (v, t), want in zip(fields, a["value"]):
                        check(float(v) == want, f"{name}: component {v} != {want}")
                        check(math.isclose(float(t), each, rel_tol=1e-12), f"{name}: tolerance {t} != {each}")
                else:
                    check(kind == "numerical", f"{name}: a number is numerical, got {kind}")
                    ans = q.findall("answer")
                    check(len(ans) == 1 and ans[0].get("fraction") == "100", f"{name}: one right answer")
                    check(float(ans[0].find("text").text) == a["value"], f"{name}: value != key's {a['value']}")
                    tol = float(ans[0].find("tolerance").text)
                    check(math.isclose(tol, a["tolerance"] * abs(a["value"]) + 1e-9, rel_tol=1e-12),
                          f"{name}: tolerance {tol}")
                    units = {u.find("unit_name").text: float(u.find("multiplier").text) for u in q.findall("units/unit")}
                    if a["unit"]:
                        check(units.get(a["unit"]) == 1.0, f"{name}: {a['unit']} with multiplier 1, got {units}")
                        for (base, other), m in MULTIPLIERS.items():
                            if base == a["unit"]:
                                check(other in units and math.isclose(units[other], m, rel_tol=1e-12),
                                      f"{name}: {other} multiplier {units.get(other)} != {m}")
                    else:
                        check(not units, f"{name}: a count has no unit")
            else:
                check(kind in ("multichoice", "essay"), f"{name}: a question without a number is {kind}")
                if kind == "multichoice":
                    fr = [a.get("fraction") for a in q.findall("answer")]
                    check(fr.count("100") == 1 and all(f in ("0", "100") for f in fr), f"{name}: fractions {fr}")
                    check(all(a.find("feedback/text").text for a in q.findall("answer")), f"{name}: every reason")
                else:
                    check(q.find("graderinfo/text").text, f"{name}: the model answer for graders")

check(any(q.get("type") == "multichoice" for qs in by_category.values() for q in qs), "a multichoice was checked")
check(any(q.get("type") == "essay" for qs in by_category.values() for q in qs), "an essay was checked")

# --format refusals: exit 2, one line naming --format, nothing written.
for bad in ["pdf", "html,html", "moodle,", "qti,moodle,qti", "QTI"]:
    d = os.path.join(tmp, "bad")
    r = subprocess.run([collide, "worksheet", "catch-up", "-o", d, "--format", bad], capture_output=True, text=True,
                       env=env)
    check(r.returncode == 2 and r.stderr.count("\n") == 1 and "--format" in r.stderr and not os.path.exists(d),
          f"--format {bad}: exit {r.returncode}, {r.stderr!r}")

# moodle alone: key.json (for collide grade) and moodle.xml, no sheets.
d = os.path.join(tmp, "only")
r = subprocess.run([collide, "worksheet", "catch-up", "-o", d, "--format", "moodle"], capture_output=True, text=True,
                   env=env)
check(r.returncode == 0 and sorted(os.listdir(d)) == ["key.json", "moodle.xml"], f"moodle alone: {os.listdir(d)}")
check("PDFs skipped" not in r.stderr, "no note about PDFs without html")

subprocess.run(["rm", "-rf", tmp])
for f in failures:
    print("FAIL:", f)
print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
