#!/usr/bin/python3
"""scripts/check_floors.py on small source trees made for the test: a tree that keeps its
floors passes; an include of a higher floor, one between sph/ and fem/, and two concepts that
include each other each fail with the finding named, as does a header that does not open with
its purpose; and grainload's own tree passes.
"""

import pathlib
import unittest

import source_trees

ROOT = pathlib.Path(__file__).resolve().parents[3]
SCRIPT = ROOT / "scripts" / "check_floors.py"


def run(root):
    return source_trees.run(SCRIPT, root)


def header(includes=""):
    """A header that opens with its purpose, then `includes`."""
    return "#pragma once\n// What it holds.\n" + includes


SOUND = {
    "io/units.hpp": header(),
    "materials/material.hpp": header('#include "io/units.hpp"\n'),
    "particles/cell_list.hpp": header('#include "io/units.hpp"\n'),
    "sph/sph_solver.hpp": header('#include "particles/cell_list.hpp"\n#include "materials/material.hpp"\n'),
    "sph/sph_solver.cpp": '#include "sph/sph_solver.hpp"\n#include <vector>\n',
    "fem/shell_model.hpp": header('#include "materials/material.hpp"\n'),
    "coupling/coupled_model.hpp": header('#include "sph/sph_solver.hpp"\n#include "fem/shell_model.hpp"\n'),
    "app/trade/trade_grid.cpp": '#include "coupling/coupled_model.hpp"\n',
}


class CheckFloors(unittest.TestCase):
    def test_a_tree_that_keeps_its_floors_passes(self):
        with source_trees.tree(SOUND) as root:
            code, out = run(root)
        self.assertEqual(code, 0, out)
        self.assertIn("7 concepts, no upward include, no cycle", out)

    def test_an_include_of_a_higher_floor_fails(self):
        with source_trees.tree({**SOUND, "materials/material.cpp": '#include "sph/sph_solver.hpp"\n'}) as root:
            code, out = run(root)
        self.assertEqual(code, 1)
        self.assertIn("materials/material includes sph/sph_solver: sph/ is not below materials/", out)

    def test_sph_and_fem_do_not_include_each_other(self):
        with source_trees.tree({**SOUND, "fem/shell_model.cpp": '#include "sph/sph_solver.hpp"\n'}) as root:
            code, out = run(root)
        self.assertEqual(code, 1)
        self.assertIn("fem/shell_model includes sph/sph_solver: sph/ is not below fem/", out)

    def test_two_concepts_that_include_each_other_fail(self):
        cycle = {"sph/wall.hpp": header(), "sph/wall.cpp": '#include "sph/rigid_wall.hpp"\n',
                 "sph/rigid_wall.hpp": header('#include "sph/wall.hpp"\n')}
        with source_trees.tree({**SOUND, **cycle}) as root:
            code, out = run(root)
        self.assertEqual(code, 1)
        self.assertIn("include cycle: sph/rigid_wall <-> sph/wall", out)

    def test_a_header_that_does_not_open_with_its_purpose_fails(self):
        for text in ('#pragma once\n#include "io/units.hpp"\n', "#pragma once\n\n// Later.\n"):
            with self.subTest(text=text):
                with source_trees.tree({**SOUND, "tests/support/csv_rows.hpp": text}) as root:
                    code, out = run(root)
                self.assertEqual(code, 1)
                self.assertIn("tests/support/csv_rows.hpp does not open with its purpose", out)

    def test_grainloads_own_tree_keeps_its_floors(self):
        code, out = run(ROOT)
        self.assertEqual(code, 0, out)


if __name__ == "__main__":
    unittest.main()
