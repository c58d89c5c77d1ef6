"""Validates JSON trace lines against src/trace/trace.schema.json and checks
that every step key is defined in lessons/vocabulary.json.

usage: validate_traces.py SCHEMA VOCABULARY FILE...   (each FILE: JSON Lines)
Exits 0 when every line is valid, 1 otherwise. Needs Debian's python3-jsonschema.
"""
import json
import sys

try:
    import jsonschema
except ImportError:
    sys.exit("validate_traces.py: python3-jsonschema is missing (apt-get install python3-jsonschema)")


def step_keys(entries):
    """Every step's key, inside groups too ({"group": ..., "steps": [...]})."""
    for entry in entries:
        if "group" in entry:
            yield from step_keys(entry["steps"])
        else:
            yield entry["key"]


def main(schema_path, vocabulary_path, *files):
    with open(schema_path, encoding="utf-8") as f:
        schema = json.load(f)
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)
    with open(vocabulary_path, encoding="utf-8") as f:
        keys = {entry["key"] for entry in json.load(f)["keys"]}
    checked = 0
    failures = 0
    for path in files:
        with open(path, encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                trace = json.loads(line)
                problems = [e.message for e in validator.iter_errors(trace)]
                problems += [f"step key {k!r} is not in the vocabulary" for k in step_keys(trace["steps"]) if k not in keys]
                for problem in problems:
                    print(f"{path}:{number}: {problem}")
                failures += bool(problems)
                checked += 1
    if checked == 0:
        print("no trace lines were given")
        return 1
    print(f"{checked} traces checked, {failures} invalid")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
