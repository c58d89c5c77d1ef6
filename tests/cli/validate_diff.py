#!/usr/bin/env python3
"""promyk diff --format json validates against src/trace/diff.schema.json.

Usage: validate_diff.py SCHEMA PROMYK A B [A B ...]: runs `promyk diff A B
--format json` for each pair and validates what it prints.
"""
import json
import subprocess
import sys

import jsonschema


def main():
    schema_path, promyk, *files = sys.argv[1:]
    with open(schema_path, encoding="utf-8") as f:
        validator = jsonschema.Draft202012Validator(json.load(f))
    checked = 0
    for a, b in zip(files[::2], files[1::2]):
        run = subprocess.run([promyk, "diff", a, b, "--format", "json"], capture_output=True, text=True, check=False)
        if run.returncode not in (0, 1):
            sys.exit(f"promyk diff {a} {b}: exit {run.returncode}: {run.stderr}")
        for error in validator.iter_errors(json.loads(run.stdout)):
            sys.exit(f"promyk diff {a} {b}: {error.json_path}: {error.message}")
        checked += 1
    print(f"{checked} diffs checked against the schema")


if __name__ == "__main__":
    main()
