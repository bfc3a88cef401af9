#!/usr/bin/env python3
"""Every `docs/NAME.md, "Section"` a comment cites must exist: the file, and a heading (# to ####) whose
title is exactly Section. A citation may break across comment lines (`docs/NAME.md,` / `// "Section"`).

Usage: check_citations.py SOURCE_DIR [FILE...]; without FILEs it reads src, include, kernels, tests,
cmake, scripts and CMakeLists.txt. Prints FILE:LINE for each broken citation and exits 1 if there is one."""
import pathlib
import re
import sys

CITATION = re.compile(r'docs/([a-z0-9-]+\.md),?[ \t]*(?:\n[ \t]*(?://+|#+|\*+)?[ \t]*)?"([^"\n]+)"')
HEADING = re.compile(r"^#{1,4}[ \t]+(.+?)[ \t]*#*[ \t]*$", re.M)
SUFFIXES = {".cpp", ".hpp", ".h", ".cl", ".cmake", ".txt", ".sh", ".py", ".in"}

source = pathlib.Path(sys.argv[1])
if len(sys.argv) > 2:
    files = [pathlib.Path(f) for f in sys.argv[2:]]
else:
    roots = [source / d for d in ("src", "include", "kernels", "tests", "cmake", "scripts")]
    files = [source / "CMakeLists.txt"] + sorted(
        f for root in roots for f in root.rglob("*") if f.is_file() and f.suffix in SUFFIXES)

headings = {}
broken = 0
cited = 0
for path in files:
    text = path.read_text(errors="replace")
    for match in CITATION.finditer(text):
        doc, title = match.groups()
        cited += 1
        line = text.count("\n", 0, match.start()) + 1
        where = f"{path.relative_to(source) if path.is_relative_to(source) else path}:{line}"
        if doc not in headings:
            doc_path = source / "docs" / doc
            headings[doc] = set(HEADING.findall(doc_path.read_text())) if doc_path.exists() else None
        if headings[doc] is None:
            print(f"{where}: cites docs/{doc}, which does not exist")
            broken += 1
        elif title not in headings[doc]:
            print(f'{where}: cites docs/{doc}, "{title}", but docs/{doc} has no heading with that title')
            broken += 1
print(f"{cited} citations of docs/ sections, {broken} broken")
sys.exit(1 if broken else 0)
