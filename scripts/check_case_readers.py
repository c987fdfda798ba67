#!/usr/bin/python3
"""Holds grainload's case schema to its readers (docs/architecture.md, "The case schema"): the
raw case table (`io::CaseTable`) is named only by io/, app/, and the readers that turn a table
into typed settings (files named *_reader.hpp/.cpp); physics takes the settings. Prints each
file that names the table elsewhere and exits 1 when there is one.

    python3 scripts/check_case_readers.py [ROOT]
"""

import pathlib
import re
import sys

import tree_check

FLOORS = ("materials", "particles", "sph", "dem", "fem", "coupling")
NAMES_TABLE = re.compile(r"\bCaseTable\b")


def is_reader(path):
    return path.stem.endswith("_reader")


def findings(root):
    found = []
    for floor in FLOORS:
        for path in sorted((root / floor).rglob("*")):
            if path.suffix not in (".hpp", ".cpp") or is_reader(path):
                continue
            name = path.relative_to(root).as_posix()
            if NAMES_TABLE.search(path.read_text(encoding="utf-8")) is not None:
                found.append(f"{name} names io::CaseTable: read the table in a *_reader file "
                             "into settings and pass those")
    return found


def main(argv):
    return tree_check.report("check_case_readers", findings(tree_check.root_of(argv)), "the raw case table is read by readers, io/ and app/ only")


if __name__ == "__main__":
    sys.exit(main(sys.argv))
