#!/usr/bin/env python3
"""The parts of docs/ that animpak prints: the parameter table of docs/parameters.md (between the
`<!-- BEGIN generated: animpak params --markdown -->` and `<!-- END generated -->` lines) and
docs/scene.schema.json (all of it, `animpak schema`).

Usage: generated_docs.py check|update ANIMPAK SOURCE_DIR params|schema ...
`check` fails, showing the difference, where the docs differ from what the code prints; `update`
rewrites them (scripts/update-docs.sh)."""
import difflib
import pathlib
import subprocess
import sys

END = "<!-- END generated -->"


def printed(animpak, args):
    return subprocess.run([animpak, *args], check=True, capture_output=True, text=True).stdout


def params_doc(animpak, source, text):
    """(current block, wanted block, the document with the wanted block) of docs/parameters.md."""
    begin = "<!-- BEGIN generated: animpak params --markdown -->"
    if text.count(begin) != 1 or text.count(END) != 1 or text.index(begin) > text.index(END):
        sys.exit(f"docs/parameters.md: expected one {begin!r} line and one {END!r} line after it")
    start = text.index(begin) + len(begin) + 1
    stop = text.index(END)
    wanted = printed(animpak, ["params", "--markdown"])
    return text[start:stop], wanted, text[:start] + wanted + text[stop:]


def main():
    mode, animpak, source, *parts = sys.argv[1:]
    source = pathlib.Path(source)
    failed = False
    for part in parts:
        if part == "params":
            path = source / "docs/parameters.md"
            current, wanted, document = params_doc(animpak, source, path.read_text())
            command = "animpak params --markdown"
        elif part == "schema":
            path = source / "docs/scene.schema.json"
            current = path.read_text() if path.exists() else ""
            wanted = document = printed(animpak, ["schema"])
            command = "animpak schema"
        else:
            sys.exit(f"unknown part {part!r}; expected params or schema")
        name = path.relative_to(source)
        if current == wanted:
            print(f"{name}: up to date with {command}")
        elif mode == "update":
            path.write_text(document)
            print(f"{name}: rewritten from {command}")
        else:
            failed = True
            sys.stdout.writelines(difflib.unified_diff(current.splitlines(True), wanted.splitlines(True),
                                                       f"{name} (as committed)", f"{command} (the code)"))
            print(f"{name} differs from {command}; run scripts/update-docs.sh and commit the result")
    sys.exit(1 if failed else 0)


main()
