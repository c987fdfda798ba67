#!/usr/bin/python3
"""Holds grainload's case schema to its readers (docs/architecture.md, "The case schema"): the
raw case table (`io::CaseTable`) is named only by io/, app/, and the readers that turn a table
into typed settings (files named *_reader.hpp/.cpp); physics takes the settings. Prints each
file that names the table elsewhere and exits 1 when there is one.

    python3 scripts/check_case_readers.py [ROOT]

STILL_READING lists the files that read their tables inside the physics they build. It only
shrinks: a file on it that no longer names the table is a finding too, so that the list stays
the true count of what is left to move into readers.
"""

import pathlib
import re
import sys

FLOORS = ("materials", "particles", "sph", "dem", "fem", "coupling")
NAMES_TABLE = re.compile(r"\bCaseTable\b")

STILL_READING = {
    "sph/particle_estimate.cpp", "sph/particle_estimate.hpp",
    "sph/sph_model.cpp", "sph/sph_model.hpp",
    "sph/sph_model_outlets.cpp", "sph/sph_model_phases.cpp", "sph/sph_model_sources.cpp",
}


def is_reader(path):
    return path.stem.endswith("_reader")


def findings(root):
    found = []
    for floor in FLOORS:
        for path in sorted((root / floor).rglob("*")):
            if path.suffix not in (".hpp", ".cpp") or is_reader(path):
                continue
            name = path.relative_to(root).as_posix()
            names = NAMES_TABLE.search(path.read_text(encoding="utf-8")) is not None
            if names and name not in STILL_READING:
                found.append(f"{name} names io::CaseTable: read the table in a *_reader file "
                             "into settings and pass those")
            elif not names and name in STILL_READING and (root / name).exists():
                found.append(f"{name} no longer names io::CaseTable: take it off STILL_READING")
    return found


def main(argv):
    root = pathlib.Path(argv[1] if len(argv) > 1 else pathlib.Path(__file__).parents[1])
    found = findings(root)
    for finding in found:
        print("check_case_readers: " + finding)
    if not found:
        left = sum(1 for name in STILL_READING if (root / name).exists())
        print(f"check_case_readers: the raw case table is read by readers, io/ and app/ only, "
              f"and by {left} files still reading inside their physics")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
