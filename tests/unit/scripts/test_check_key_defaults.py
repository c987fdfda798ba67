#!/usr/bin/python3
"""scripts/check_key_defaults.py on small source trees made for the test: defaults taken from
the declaration, computed from the scene or absent pass; a number, a boolean, a word or a
constant vector written again at the call fails, also when the call spans lines; an LS-DYNA card's field (no key name)
is not a case key; and grainload's own tree passes.
"""

import pathlib
import unittest

import source_trees

ROOT = pathlib.Path(__file__).resolve().parents[3]
SCRIPT = ROOT / "scripts" / "check_key_defaults.py"

SOUND = {
    "sph/sph_case_reader.cpp": (
        'const double s = wall.positive_quantity_or("spacing", dim::kLength, body_spacing);\n'
        'const bool open = wall.boolean_or("open_top", io::default_value(kWallKeys, "open_top") != 0.0);\n'
        'const auto kernel = sph.choice_or("kernel", {"cubic", "quintic"},\n'
        '                                  io::default_text(kSphKeys, "kernel"));\n'
        'const std::string source = table.string_or("source", "");\n'),
    "io/keyword_mesh.cpp": "section.element_form = static_cast<int>(f1.integer_or(1, 0));\n",
}


def run(root):
    return source_trees.run(SCRIPT, root)


class CheckKeyDefaults(unittest.TestCase):
    def test_declared_computed_and_empty_defaults_pass(self):
        with source_trees.tree(SOUND) as root:
            code, out = run(root)
        self.assertEqual(code, 0, out)
        self.assertIn("every key's default comes from its declaration", out)

    def test_literal_defaults_fail(self):
        for call, shown in (('table.integer_or("seed", 1)', "1"),
                            ('table.boolean_or("rotation", true)', "true"),
                            ('dem.positive_quantity_or("start", dim::kTime, 0.0, true)', "0.0"),
                            ('table.vector_or("axis", dim::kNone, Vec3::UnitX())', "Vec3::UnitX()"),
                            ('fem.choice_or("mass",\n    {"lumped", "consistent"}, "lumped")',
                             '"lumped"')):
            with self.subTest(call=call):
                files = {**SOUND, "dem/dem_case_reader.cpp": f"x = {call};\n"}
                with source_trees.tree(files) as root:
                    code, out = run(root)
                self.assertEqual(code, 1)
                self.assertIn("dem/dem_case_reader.cpp:1:", out)
                self.assertIn(f"falls back to the literal {shown}", out)

    def test_grainloads_own_tree_passes(self):
        code, out = run(ROOT)
        self.assertEqual(code, 0, out)


if __name__ == "__main__":
    unittest.main()
