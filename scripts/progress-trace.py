#!/usr/bin/env python3
"""Turns a packed folder's stats.json into a progress trace: the rows `pack` saw at every statistics check,
with what StopModel needs to replay them (the world's unit mesh density, the stop test's stall window,
growth and tests per window, whether secondary elements wait). tests/solver/test_progress.cpp replays
every trace in tests/solver/traces/ and checks the time left it would have printed.

    scripts/progress-trace.py DIR/stats.json "animpak pack SCENE --no-render" > tests/solver/traces/NAME.csv
"""
import json
import sys


def main() -> int:
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 1
    with open(sys.argv[1], encoding="utf-8") as f:
        stats = json.load(f)
    progress = stats.get("progress", {})
    if "unit_mesh_density" not in progress or "stall" not in progress:
        print(f"{sys.argv[1]}: no unit_mesh_density or stall in its progress (written before 0.17.0); pack again",
              file=sys.stderr)
        return 2
    stall = progress["stall"]
    print(f"# {sys.argv[2]}: {stats['elements']} elements, {stats['vertices']} vertices, stop {stats['stop_reason']} "
          f"at {stats['iterations']}, on {stats['device']}, commit {stats['commit']}")
    print(f"# unit_mesh_density: {progress['unit_mesh_density']:.6f}")
    print(f"# stall: {stall['window']} {stall['growth']} {stall['tests']}")
    if progress.get("secondary"):
        print(f"# secondary: growing from iteration {stats.get('secondary_since', 0)}")
    print(",".join(progress["columns"]))
    for row in progress["rows"]:
        print(",".join("" if v is None else repr(v) for v in row))
    return 0


if __name__ == "__main__":
    sys.exit(main())
