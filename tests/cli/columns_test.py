#!/usr/bin/env python3
"""Every text output fits 80 columns (display width in code points), in
Polish and English: lesson --list, every lesson with its default pixels and
other pixels, worksheets with their keys, traces of every example scene
(narrow layout) and their comparisons, scene check, the bench's tables, and the messages of
common mistakes. `trace --wide` and `--help` are exempt, as the issue allows.

usage: columns_test.py PROMYK LESSONS_DIR"""
import glob
import json
import os
import subprocess
import sys

promyk, lessons = sys.argv[1], sys.argv[2]
COLUMNS = 80
failures = []
checked = 0


def run(args, expect_ok=True):
    global checked
    env = dict(os.environ, LANG="C.UTF-8", LC_ALL="", LC_MESSAGES="")
    result = subprocess.run([promyk] + args, capture_output=True, env=env, timeout=120)
    if expect_ok and result.returncode != 0:
        failures.append(f"{' '.join(args)}: exit {result.returncode}: {result.stderr.decode()[:300]}")
        return
    for stream, name in ((result.stdout, "stdout"), (result.stderr, "stderr")):
        for number, line in enumerate(stream.decode("utf-8").split("\n"), 1):
            checked += 1
            line = line.replace("\x1b[1m", "").replace("\x1b[0m", "")
            if len(line) > COLUMNS:
                failures.append(f"promyk {' '.join(args)}: {name} line {number} has {len(line)} columns:\n    {line}")


names = sorted(os.path.basename(p)[3:-3] for p in glob.glob(os.path.join(lessons, "en", "*.md")))
scenes = sorted(p for p in glob.glob(os.path.join(lessons, "scenes", "*.json")) if not p.endswith("schema.json"))

for lang in ("pl", "en"):
    run(["lesson", "--list", "--lang", lang])
    for name in names:
        run(["lesson", name, "--lang", lang])
        run(["lesson", name, "--lang", lang, "--pixel", "0,0", "--pixel", "7,7"])
        run(["lesson", name, "--lang", lang, "--worksheet", "--key"])
        run(["lesson", name, "--lang", lang, "--worksheet", "--pixel", "1,2", "--pixel", "3,4", "--pixel", "5,1",
             "--real", "long-double", "--formula", "geometric", "--spp", "4"])
    # the bench's tables, at the smallest sizes (the layout, not the timings)
    run(["bench", "speed", "--lang", lang, "--w", "8", "--repetitions", "1", "--trace-w", "4"], expect_ok=False)
    run(["bench", "effects", "--lang", lang, "--w", "4", "--repetitions", "1"])
    run(["bench", "accuracy", "--lang", lang, "--w", "4", "--repetitions", "1", "--spp", "1,4",
         "--real", "long-double", "--formula", "geometric"])
    for scene in scenes:
        run(["scene", "check", scene, "--lang", lang])
        for pixel in ("0,0", "3,4", "5,1", "4,4", "7,2"):
            run(["trace", "--scene", scene, "--pixel", pixel, "--lang", lang, "--explain"])
        run(["trace", "--scene", scene, "--pixel", "3,4", "--lang", lang, "--real", "quad", "--spp", "4"])
        run(["trace", "--scene", scene, "--pixel", "3,4", "--lang", lang, "--compare", "float,double,long-double,quad"])
    # diff of two types, and the answer check of a file with every kind of line
    import tempfile
    with tempfile.TemporaryDirectory() as tmp:
        for real in ("float", "quad"):
            env = dict(os.environ, LANG="C.UTF-8", LC_ALL="", LC_MESSAGES="")
            with open(os.path.join(tmp, real + ".json"), "wb") as f:
                f.write(subprocess.run([promyk, "trace", "--real", real, "--format", "json"], capture_output=True, env=env).stdout)
        run(["diff", os.path.join(tmp, "float.json"), os.path.join(tmp, "quad.json"), "--lang", lang], expect_ok=False)
        answers = os.path.join(tmp, "answers.txt")
        with open(answers, "w") as f:
            f.write("[3,4]\nEE = 129/32\nC = 6,41\ndelta = 4.5578125000000043\nt = 1.06\ndetla = 4\nP.z = two point one\nt = 1\n")
        run(["lesson", "sphere", "--pixel", "3,4", "--answers", answers, "--lang", lang], expect_ok=False)
    # mistakes a user makes
    run(["trace", "--pixel", "200,300", "--lang", lang], expect_ok=False)
    run(["trace", "--real", "flaot", "--lang", lang], expect_ok=False)
    run(["lesson", "sphre", "--lang", lang], expect_ok=False)
    run(["render", "--map", "eror", "--lang", lang], expect_ok=False)

for failure in failures:
    print("FAIL:", failure)
print(f"{checked - len(failures)} passed, {len(failures)} failed")
sys.exit(1 if failures else 0)
