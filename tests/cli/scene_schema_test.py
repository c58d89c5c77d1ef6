"""The scene schema and the scene loader agree.

usage: scene_schema_test.py PROMYK SCHEMA SCENE_FILE...
- every scene the loader accepts (promyk scene check: exit 0) validates
  against lessons/scenes/scene.schema.json, and every scene that fails the
  schema the loader rejects (exit 3); the loader may reject more (the eye
  inside the sphere, a NUL byte, a duplicate key: what a schema cannot say);
- promyk scene dump writes exactly the keys the schema defines, at every level.
Needs Debian's python3-jsonschema.
"""
import json
import os
import subprocess
import sys
import tempfile

try:
    import jsonschema
except ImportError:
    sys.exit("scene_schema_test.py: python3-jsonschema is missing (apt-get install python3-jsonschema)")


def main(promyk, schema_path, *scenes):
    with open(schema_path, encoding="utf-8") as f:
        schema = json.load(f)
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)
    passed = failed = 0

    def check(ok, what):
        nonlocal passed, failed
        if ok:
            passed += 1
        else:
            failed += 1
            print("FAIL:", what)

    for path in scenes:
        code = subprocess.run([promyk, "scene", "check", path], capture_output=True).returncode
        try:
            with open(path, encoding="utf-8") as f:
                document = json.load(f)
            valid = not list(validator.iter_errors(document))
        except (ValueError, UnicodeDecodeError):
            valid = False  # not JSON at all: the schema cannot accept it
        if code == 0:
            check(valid, f"{path}: the loader accepts it, the schema does not")
        else:
            check(code == 3, f"{path}: the loader exits {code} (expected 0 or 3)")
        if not valid:
            check(code == 3, f"{path}: the schema rejects it, the loader exits {code}")

    # Faults a schema can state: the loader and the schema both refuse each.
    base = {"spheres": [{"S": [0, 0, 3.2], "r": 1.1}], "lights": [{"L": [1.5, 1, 1], "I": 1}]}
    variants = {
        "r = 0": {**base, "spheres": [{"S": [0, 0, 3.2], "r": 0}]},
        "r < 0": {**base, "spheres": [{"S": [0, 0, 3.2], "r": -1}]},
        "no r": {**base, "spheres": [{"S": [0, 0, 3.2]}]},
        "S of 2 numbers": {**base, "spheres": [{"S": [0, 3.2], "r": 1}]},
        "two spheres": {**base, "spheres": base["spheres"] * 2},
        "no lights": {"spheres": base["spheres"], "lights": []},
        "no L": {**base, "lights": [{"I": 1}]},
        "I < 0": {**base, "lights": [{"L": [1, 1, 1], "I": -0.5}]},
        "z_E = 0": {**base, "z_E": 0},
        "background 2": {**base, "background": 2},
        "empty name": {**base, "name": ""},
        "name with a control character": {**base, "name": "a\u0007b"},
        "unknown key": {**base, "comment": "x"},
        "unknown sphere key": {**base, "spheres": [{"S": [0, 0, 3.2], "r": 1, "colour": 1}]},
        "S a string": {**base, "spheres": [{"S": "0 0 3", "r": 1}]},
    }
    with tempfile.TemporaryDirectory() as folder:
        for what, document in variants.items():
            path = os.path.join(folder, "scene.json")
            with open(path, "w", encoding="utf-8") as f:
                json.dump(document, f)
            code = subprocess.run([promyk, "scene", "check", path], capture_output=True).returncode
            check(code == 3, f"{what}: the loader exits {code}, expected 3")
            check(bool(list(validator.iter_errors(document))), f"{what}: the schema accepts it")

    dump = json.loads(subprocess.run([promyk, "scene", "dump"], capture_output=True, check=True).stdout)
    check(not list(validator.iter_errors(dump)), "the dump validates")
    check(set(dump) == set(schema["properties"]), f"top-level keys: dump {sorted(dump)}")
    check(set(dump["spheres"][0]) == set(schema["$defs"]["sphere"]["properties"]), "sphere keys")
    check(set(dump["lights"][0]) == set(schema["$defs"]["light"]["properties"]), "light keys")
    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
