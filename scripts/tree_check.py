"""What grainload's tree checks share (scripts/check_case_readers.py, check_key_defaults.py):
the tree's root from the command line, and the report of their findings."""

import pathlib


def root_of(argv):
    """The tree the check reads: ROOT from the command line, else the one the script is in."""
    return pathlib.Path(argv[1] if len(argv) > 1 else pathlib.Path(__file__).parents[1])


def report(check, found, sound):
    """Prints each finding, or `sound` when there is none, after the check's name; the exit
    code: 1 with findings."""
    for finding in found:
        print(f"{check}: {finding}")
    if not found:
        print(f"{check}: {sound}")
    return 1 if found else 0
