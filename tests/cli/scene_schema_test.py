"""The scene schema and the scene loader agree.

usage: scene_schema_test.py PROMYK SCHEMA SCENE_FILE...
- every scene the loader accepts (promyk scene check: exit 0) validates
  against lessons/scenes/scene.schema.json, and every scene that fails the
  schema the loader rejects (exit 3); the loader may reject more (a material
  index that names no material, a normal too short or too long for doubles,
  no object at all, a NUL byte, a duplicate key: what a schema cannot say);
- promyk scene dump --all writes exactly the keys the schema defines, at
  every level (an object's "material" only when it has one).
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

    def loader_exit(path):
        return subprocess.run([promyk, "scene", "check", path], capture_output=True).returncode

    for path in scenes:
        code = loader_exit(path)
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

    base = {"spheres": [{"S": [0, 0, 3.2], "r": 1.1}], "lights": [{"L": [1.5, 1, 1], "I": 1}]}
    sphere = base["spheres"][0]
    plane = {"Q": [0, -1.1, 0], "n": [0, 1, 0]}

    def with_material(material):
        return {**base, "spheres": [{**sphere, "material": 0}], "materials": [material]}

    # Faults a schema can state: the loader and the schema both refuse each.
    both_refuse = {
        "r = 0": {**base, "spheres": [{"S": [0, 0, 3.2], "r": 0}]},
        "r < 0": {**base, "spheres": [{"S": [0, 0, 3.2], "r": -1}]},
        "no r": {**base, "spheres": [{"S": [0, 0, 3.2]}]},
        "S of 2 numbers": {**base, "spheres": [{"S": [0, 3.2], "r": 1}]},
        "no lights": {"spheres": base["spheres"], "lights": []},
        "no lights key": {"spheres": base["spheres"]},
        "no L": {**base, "lights": [{"I": 1}]},
        "I < 0": {**base, "lights": [{"L": [1, 1, 1], "I": -0.5}]},
        "z_E = 0": {**base, "z_E": 0},
        "background 2": {**base, "background": 2},
        "background [2, 0, 0]": {**base, "background": [2, 0, 0]},
        "background of 2 numbers": {**base, "background": [0.5, 0.5]},
        "background a string": {**base, "background": "grey"},
        "shadows \"yes\"": {**base, "shadows": "yes"},
        "shadows 1": {**base, "shadows": 1},
        "empty name": {**base, "name": ""},
        "name with a control character": {**base, "name": "a\u0007b"},
        "unknown key": {**base, "comment": "x"},
        "unknown sphere key": {**base, "spheres": [{"S": [0, 0, 3.2], "r": 1, "colour": 1}]},
        "S a string": {**base, "spheres": [{"S": "0 0 3", "r": 1}]},
        "planes an object": {**base, "planes": {}},
        "materials a number": {**base, "materials": 1},
        "zero normal": {**base, "planes": [{**plane, "n": [0, 0, 0]}]},
        "plane without n": {**base, "planes": [{"Q": [0, 0, 0]}]},
        "plane without Q": {**base, "planes": [{"n": [0, 1, 0]}]},
        "unknown plane key": {**base, "planes": [{**plane, "normal": [0, 1, 0]}]},
        "negative material index": {**base, "spheres": [{**sphere, "material": -1}], "materials": [{}]},
        "fractional material index": {**base, "spheres": [{**sphere, "material": 0.5}], "materials": [{}]},
        "material index a string": {**base, "planes": [{**plane, "material": "0"}], "materials": [{}]},
        "negative ambient": with_material({"ambient": -0.1}),
        "negative diffuse": with_material({"diffuse": -1}),
        "negative specular": with_material({"specular": -0.5}),
        "exponent 0": with_material({"exponent": 0}),
        "exponent 2.5": with_material({"exponent": 2.5}),
        "exponent 10001": with_material({"exponent": 10001}),
        "exponent 1e300": with_material({"exponent": 1e300}),
        "material colour 1.5": with_material({"colour": [1, 1, 1.5]}),
        "unknown material key": with_material({"shininess": 20}),
        "light colour of 2 numbers": {**base, "lights": [{"L": [1, 1, 1], "colour": [1, 0.5]}]},
        "light colour negative": {**base, "lights": [{"L": [1, 1, 1], "colour": [1, -0.5, 1]}]},
    }
    # Faults only the loader sees: it refuses each, and the schema, which
    # says in its description that it cannot, accepts each.
    loader_refuses = {
        "no objects": {"lights": base["lights"]},
        "empty object lists": {"spheres": [], "planes": [], "lights": base["lights"]},
        "a material that does not exist": {**base, "spheres": [{**sphere, "material": 1}], "materials": [{}]},
        "a material index without materials": {**base, "spheres": [{**sphere, "material": 0}]},
        "a plane too far": {**base, "planes": [{"Q": [1.5e308, 1.5e308, 0], "n": [1, 1, 0]}]},
    }
    # The new fields at their limits: both accept.
    both_accept = {
        "planes only": {"planes": [plane], "lights": base["lights"]},
        "every field": {"name": "all", "z_E": 1, "background": [0, 0.5, 1], "shadows": True,
                        "spheres": [{**sphere, "material": 1}], "planes": [{**plane, "material": 0}],
                        "lights": [{"L": [1, 1, 1], "I": 0, "colour": [0, 0, 1]}],
                        "materials": [{}, {"ambient": 0, "diffuse": 0, "specular": 2, "exponent": 10000,
                                           "colour": [0, 0, 0]}]},
        "whole numbers written as decimals": {**base, "spheres": [{**sphere, "material": 0.0}],
                                              "materials": [{"exponent": 20.0}]},
        "exponent 1": with_material({"exponent": 1}),
        "a tiny normal": {**base, "planes": [{**plane, "n": [0, 1e-200, 0]}]},
        "a huge normal": {**base, "planes": [{**plane, "n": [0, 1e200, 0]}]},
        "the eye inside a sphere": {**base, "spheres": [{"S": [0, 0, 1], "r": 2}]},
        "many spheres and lights": {**base, "spheres": [sphere] * 5, "lights": base["lights"] * 3},
    }
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "scene.json")
        for cases, loader_code, schema_valid in ((both_refuse, 3, False), (loader_refuses, 3, True),
                                                 (both_accept, 0, True)):
            for what, document in cases.items():
                with open(path, "w", encoding="utf-8") as f:
                    json.dump(document, f)
                code = loader_exit(path)
                check(code == loader_code, f"{what}: the loader exits {code}, expected {loader_code}")
                valid = not list(validator.iter_errors(document))
                check(valid == schema_valid, f"{what}: the schema {'rejects' if schema_valid else 'accepts'} it")

    dump = json.loads(subprocess.run([promyk, "scene", "dump"], capture_output=True, check=True).stdout)
    check(not list(validator.iter_errors(dump)), "the dump validates")
    everything = [path for path in scenes if os.path.basename(path) == "everything.json"]
    check(len(everything) == 1, "lessons/scenes/everything.json is among the scenes")
    defs = schema["$defs"]
    for args in (["scene", "dump", "--all"], ["scene", "dump", "--all", "--scene", *everything[:1]]):
        dump = json.loads(subprocess.run([promyk, *args], capture_output=True, check=True).stdout)
        check(not list(validator.iter_errors(dump)), f"{args}: the dump validates")
        check(set(dump) == set(schema["properties"]), f"{args}: top-level keys {sorted(dump)}")
        for key, kind in (("spheres", "sphere"), ("planes", "plane")):
            for item in dump[key]:
                keys = set(defs[kind]["properties"]) - (set() if "material" in item else {"material"})
                check(set(item) == keys, f"{args}: {kind} keys {sorted(item)}")
        for key, kind in (("lights", "light"), ("materials", "material")):
            for item in dump[key]:
                check(set(item) == set(defs[kind]["properties"]), f"{args}: {kind} keys {sorted(item)}")
    check(bool(dump["planes"]) and bool(dump["materials"]), "everything.json's dump has planes and materials")
    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
