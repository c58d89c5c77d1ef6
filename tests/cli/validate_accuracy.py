#!/usr/bin/env python3
"""promyk bench accuracy --json validates against src/bench/accuracy.schema.json,
and says what it promises beyond the schema.

usage: validate_accuracy.py SCHEMA FILE...
Checks, besides the schema: every result names a scene of the file; there is
one result per scene x spp x real x formula of the run (no gaps, no
duplicates); the reference's own combination (quad/geometric) has no error
and no differing branch; a ratio is null exactly when the result says why
(untimed), timeable says whether every ratio is given, and the runs were
timed as promyk render runs without --stats (counts_branches false). Exits 0 when every file is valid, 1 otherwise.
Needs Debian's python3-jsonschema.
"""
import json
import sys

try:
    import jsonschema
except ImportError:
    sys.exit("validate_accuracy.py: python3-jsonschema is missing (apt-get install python3-jsonschema)")


def problems_of(data, validator):
    problems = [f"{'/'.join(map(str, e.absolute_path))}: {e.message}" for e in validator.iter_errors(data)]
    if problems:
        return problems
    names = [s["name"] for s in data["scenes"]]
    results = data["results"]
    keys = [(r["scene"], r["spp"], r["real"], r["formula"]) for r in results]
    if len(set(keys)) != len(keys):
        problems.append("a scene × spp × real × formula appears twice")
    axes = [sorted({k[n] for k in keys}, key=str) for n in range(4)]
    expected = len(axes[0]) * len(axes[1]) * len(axes[2]) * len(axes[3])
    if len(keys) != expected:
        problems.append(f"{len(keys)} results, expected every combination of the run's axes: {expected}")
    for r in results:
        where = f"{r['scene']} spp {r['spp']} {r['real']}/{r['formula']}"
        if r["scene"] not in names:
            problems.append(f"{where}: scene not in scenes")
        if r["pixels"] != data["w"] ** 2:
            problems.append(f"{where}: pixels {r['pixels']}, expected w² = {data['w'] ** 2}")
        if (r["real"], r["formula"]) == ("quad", "geometric") and (r["max_error"] != 0 or r["branch_differs"] != 0):
            problems.append(f"{where}: the reference's own combination differs from the reference")
        if (r["ratio"] is None) != ("untimed" in r):
            problems.append(f"{where}: ratio {r['ratio']} but untimed is {r.get('untimed')!r}")
    if data["timeable"] != all(r["ratio"] is not None for r in results):
        problems.append(f"timeable is {data['timeable']} but the ratios say otherwise")
    if data["counts_branches"] is not False:
        problems.append("counts_branches is not false: the runs were not timed as promyk render runs without --stats")
    return problems


def main(schema_path, *files):
    with open(schema_path, encoding="utf-8") as f:
        schema = json.load(f)
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)
    failures = 0
    checked = 0
    for path in files:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
        for problem in problems_of(data, validator):
            print(f"{path}: {problem}")
            failures += 1
        checked += len(data.get("results", []))
    if not files:
        print("no files were given")
        return 1
    print(f"{checked} results checked, {failures} problems")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
