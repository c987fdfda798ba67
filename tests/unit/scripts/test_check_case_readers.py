#!/usr/bin/python3
"""scripts/check_case_readers.py on small source trees made for the test: a reader that names
the raw case table passes; a physics file that names it fails (a header as well as a source);
and grainload's own tree passes.
"""

import pathlib
import unittest

import source_trees

ROOT = pathlib.Path(__file__).resolve().parents[3]
SCRIPT = ROOT / "scripts" / "check_case_readers.py"


def run(root):
    return source_trees.run(SCRIPT, root)


SOUND = {
    "io/case_table.hpp": "class CaseTable;\n",
    "particles/particles_case_reader.cpp": "SinkSet read_sinks(const io::CaseTable& scene);\n",
    "particles/sink.hpp": "SinkSet(std::vector<Sink> sinks, int dimension);\n",
    "app/scene.cpp": "const io::CaseTable root = document.root();\n",
}


class CheckCaseReaders(unittest.TestCase):
    def test_readers_io_and_app_may_name_the_table(self):
        with source_trees.tree(SOUND) as root:
            code, out = run(root)
        self.assertEqual(code, 0, out)
        self.assertIn("read by readers, io/ and app/ only", out)

    def test_physics_that_names_the_table_fails(self):
        with source_trees.tree({**SOUND, "particles/sink.cpp": "SinkSet::SinkSet(const io::CaseTable& t)\n"}) as root:
            code, out = run(root)
        self.assertEqual(code, 1)
        self.assertIn("particles/sink.cpp names io::CaseTable", out)

    def test_a_physics_header_that_names_the_table_fails(self):
        with source_trees.tree({**SOUND, "sph/sph_model.hpp": "void build(const io::CaseTable& root);\n"}) as root:
            code, out = run(root)
        self.assertEqual(code, 1)
        self.assertIn("sph/sph_model.hpp names io::CaseTable", out)

    def test_grainloads_own_tree_passes(self):
        code, out = run(ROOT)
        self.assertEqual(code, 0, out)


if __name__ == "__main__":
    unittest.main()
