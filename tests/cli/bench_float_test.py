#!/usr/bin/env python3
"""bench speed's --real float line, checked through the traced path: the
largest difference in intensity from double, its pixel, and the number of
pixels whose grey level differs, recomputed from every pixel's trace in
float and in double (render --traces), in English and in Polish.

usage: bench_float_test.py PROMYK WORK_DIR"""
import json
import os
import re
import subprocess
import sys

promyk, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)
W = 128
failures = []


def run(args):
    env = dict(os.environ, LANG="C.UTF-8", LC_ALL="", LC_MESSAGES="")
    result = subprocess.run([promyk] + args, capture_output=True, env=env, timeout=300, cwd=work)
    if result.returncode != 0:
        sys.exit(f"{' '.join(args)}: exit {result.returncode}: {result.stderr.decode()[:500]}")
    return result.stdout.decode("utf-8")


def traces(real):
    run(["render", "--w", str(W), "--real", real, "-o", f"{real}.pgm", "--traces", f"{real}.jsonl",
         "--trace-region", f"0,0,{W - 1},{W - 1}"])
    pixels = {}
    with open(os.path.join(work, f"{real}.jsonl"), encoding="utf-8") as lines:
        for line in lines:
            trace = json.loads(line)
            pixels[(trace["pixel"]["i"], trace["pixel"]["j"])] = (trace["result"], trace["grey"])
    return pixels


as_float, as_double = traces("float"), traces("double")
if len(as_float) != W * W or len(as_double) != W * W:
    sys.exit(f"expected {W * W} traces each, got {len(as_float)} and {len(as_double)}")
largest = max(abs(as_float[p][0] - as_double[p][0]) for p in as_double)
at = [p for p in as_double if abs(as_float[p][0] - as_double[p][0]) == largest]
greys = sum(as_float[p][1] != as_double[p][1] for p in as_double)


def number(text):
    return float(text.replace(",", ".").replace("\u2212", "-"))


for lang, pattern in (
        ("en", r"largest difference in intensity from double: (\S+), at pixel \((\d+), (\d+)\);\s+another grey level:\s+(\d+) pixel"),
        ("pl", r"największa różnica natężeń względem double: (\S+), w pikselu \((\d+), (\d+)\);\s+inny poziom szarości:\s+(\d+) piksel")):
    out = run(["--lang", lang, "bench", "speed", "--w", str(W), "--repetitions", "1", "--trace-w", "4"])
    found = re.search(pattern, out)
    if not found:
        failures.append(f"{lang}: no float line in:\n{out}")
        continue
    shown, i, j, count = number(found.group(1)), int(found.group(2)), int(found.group(3)), int(found.group(4))
    if abs(shown - largest) > 0.0051 * largest:  # shown to 3 significant digits
        failures.append(f"{lang}: largest difference {shown}, traces give {largest}")
    if (i, j) not in at:
        failures.append(f"{lang}: at pixel ({i}, {j}), traces give {at}")
    if count != greys:
        failures.append(f"{lang}: {count} grey levels differ, traces give {greys}")
    if not re.search(r"float \(--real float\), 1 (thread|wątek)[^:]*: [0-9]+[.,][0-9]+\s+ns/pi", out):
        failures.append(f"{lang}: no float timing in:\n{out}")

if failures:
    print("\n".join(failures))
    sys.exit(1)
print(f"float against double at w = {W}: largest difference {largest:.3g} at {at}, {greys} grey levels differ; "
      "bench speed agrees in en and pl")
