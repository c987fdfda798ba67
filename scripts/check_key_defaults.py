#!/usr/bin/python3
"""Holds each case key to one default (docs/architecture.md, "The case schema"): the default a
reader falls back to when a key is absent comes from the key's declaration (io::default_value,
io::default_text), not from a literal written again at the call. Prints each call of a
CaseTable `*_or` accessor in a reader whose default is a number, true/false, a non-empty
string literal or a constant vector, and exits 1 when there is one. A default computed from the scene (the bodies'
spacing, the end time over 20) is what the declaration states in words and passes.

    python3 scripts/check_key_defaults.py [ROOT]
"""

import pathlib
import re
import sys

import tree_check

FLOORS = ("io", "materials", "particles", "sph", "dem", "fem", "coupling", "app")
CALL = re.compile(
    r"\.(number|integer|boolean|choice|string|quantity|positive_quantity|vector)_or\(")
# The argument that holds the default, by accessor: number_or(key, default), choice_or(key,
# choices, default), quantity_or(key, dimension, default, ...).
DEFAULT_ARGUMENT = {"number": 1, "integer": 1, "boolean": 1, "string": 1, "choice": 2,
                    "quantity": 2, "positive_quantity": 2, "vector": 2}
LITERAL = re.compile(r'^(-?[0-9][0-9.]*(e-?[0-9]+)?|true|false|"[^"]+"|'
                     r'Vec3::(Zero|UnitX|UnitY|UnitZ)\(\)|Vec3\([-0-9.e, ]+\))$')


def arguments(text, start):
    """The top-level arguments of the call whose '(' is at text[start - 1]."""
    depth, current, found = 0, [], []
    for i in range(start, len(text)):
        c = text[i]
        if c in "([{":
            depth += 1
        elif c in ")]}":
            if depth == 0:
                found.append("".join(current).strip())
                return found
            depth -= 1
        elif c == "," and depth == 0:
            found.append("".join(current).strip())
            current = []
            continue
        current.append(c)
    return found


def findings(root):
    found = []
    for floor in FLOORS:
        for path in sorted((root / floor).rglob("*.cpp")):
            text = path.read_text(encoding="utf-8")
            for match in CALL.finditer(text):
                args = arguments(text, match.end())
                index = DEFAULT_ARGUMENT[match.group(1)]
                if not args or not args[0].startswith('"') or len(args) <= index:
                    continue  # not a case key (an LS-DYNA card's field)
                if LITERAL.match(" ".join(args[index].split())):
                    line = text.count("\n", 0, match.start()) + 1
                    name = path.relative_to(root).as_posix()
                    found.append(f"{name}:{line}: {args[0]} falls back to the literal "
                                 f"{args[index]}: take the declared default")
    return found


def main(argv):
    return tree_check.report("check_key_defaults", findings(tree_check.root_of(argv)), "every key's default comes from its declaration")


if __name__ == "__main__":
    sys.exit(main(sys.argv))
