#!/usr/bin/env python3
"""Validates the scene files of the repository against docs/scene.schema.json with python3-jsonschema, a
validator independent of animpak's parser, and checks that the schema rejects an unknown key at every
level where the parser does (tests/io/test_scene_file.cpp holds the parser's side of the same cases).

Usage: validate_scenes.py SOURCE_DIR. Exits 77 (skipped) when python3-jsonschema is missing, 1 under CI=true."""
import copy
import json
import pathlib
import sys

try:
    import jsonschema
except ImportError:
    import os
    if os.environ.get("CI") == "true":  # CI installs every tool: a skip there hides a missing install step
        print("CI=true, where nothing may skip: python3-jsonschema is not installed (scripts/install-deps.sh)")
        sys.exit(1)
    print("skipped: python3-jsonschema is not installed (scripts/install-deps.sh)")
    sys.exit(77)

source = pathlib.Path(sys.argv[1])
schema = json.loads((source / "docs/scene.schema.json").read_text())
jsonschema.Draft202012Validator.check_schema(schema)
validator = jsonschema.Draft202012Validator(schema)

scenes = (sorted(source.glob("examples/**/*.json")) + sorted(source.glob("tests/golden/**/scene*.json")) +
          [source / "tests/io/every-object.json"])
if not scenes:
    sys.exit("no scene files found under examples/ and tests/golden/")
failures = 0
for path in scenes:
    errors = list(validator.iter_errors(json.loads(path.read_text())))
    for error in errors:
        where = "/".join(str(p) for p in error.absolute_path) or "top level"
        print(f"FAIL {path.relative_to(source)}: {where}: {error.message}")
    failures += bool(errors)
    if not errors:
        print(f"ok   {path.relative_to(source)}")

# A scene with every object of the format; the parser's test plants the same keys in the same file.
every = json.loads((source / "tests/io/every-object.json").read_text())


def objects(value, where="top level"):
    """Every object of `value` with its field path, as the parser names it."""
    if isinstance(value, dict):
        yield where, value
        for key, inner in value.items():
            yield from objects(inner, key if where == "top level" else f"{where}.{key}")
    elif isinstance(value, list):
        for i, inner in enumerate(value):
            yield from objects(inner, f"{where}[{i}]")


count = 0
for where, _ in list(objects(every)):
    scene = copy.deepcopy(every)
    target = dict(objects(scene))[where]
    target["unknown_key"] = 1
    count += 1
    if validator.is_valid(scene):
        failures += 1
        print(f"FAIL the schema accepts an unknown key in {where}")
    else:
        print(f"ok   the schema rejects an unknown key in {where}")
if count < 12:
    failures += 1
    print(f"FAIL tests/io/every-object.json has {count} objects; fewer than the 12 kinds of object the format has")
sys.exit(1 if failures else 0)
