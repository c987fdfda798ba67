#!/usr/bin/python3
"""scripts/check_history.py on a small git repository made for the test: a line in product
language passes, each kind of history reference fails with its kind named, and the phrases that
look like one but are not (a CalculiX element, a steel grade, a float, a colour, a generated
record, a path that a glob, a brace form, a placeholder, a run or a build makes) pass.

The references are the rules the script documents; every expectation below is one of them.
"""

import os
import pathlib
import subprocess
import sys
import tempfile
import unittest

SCRIPTS = pathlib.Path(__file__).resolve().parents[3] / "scripts"
sys.path.insert(0, str(SCRIPTS))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree

import check_history  # noqa: E402  (found through SCRIPTS)

FILES = {
    "app/trade_command.hpp": "", "app/trade_command.cpp": "", "app/trade_grid.hpp": "",
    "app/trade_grid.cpp": "", "bench/sph_throughput.cpp": "", "cmake/version.hpp.in": "",
    "cases/silo/silo_small.toml": "", "cases/hopper/hopper_small.toml": "",
    "docs/validation/silo.md": "# Silo\n", "docs/performance.md": "# Performance\n",
    ".gitignore": "/build*/\n/cases/silo/*.msh\n",
}


def make_repo(root, extra=None):
    for path, text in {**FILES, **(extra or {})}.items():
        full = os.path.join(root, path)
        os.makedirs(os.path.dirname(full) or root, exist_ok=True)
        with open(full, "w", encoding="utf-8") as f:
            f.write(text)
    subprocess.run(["git", "init", "-q", root], check=True)
    subprocess.run(["git", "-C", root, "add", "-A"], check=True)


class CheckHistoryTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.folder = tempfile.TemporaryDirectory()
        make_repo(cls.folder.name)
        cls.tree = check_history.Tree(cls.folder.name, check_history.git_files(cls.folder.name))

    @classmethod
    def tearDownClass(cls):
        cls.folder.cleanup()

    def kinds(self, text, path="docs/page.md"):
        return [kind for _, kind, _ in check_history.scan_text(path, text, self.tree)]

    def test_product_language_passes(self):
        for line in [
            "The default is 0.3 because the 3D, cap and coupled cases have not been swept.",
            "Measured with `grainload run cases/silo/silo_small.toml` on a 2-core AMD EPYC.",
            "Beverloo, Leniger & van de Velde (1961); EN 1991-4 Eq. 5.5; docs/validation/silo.md.",
        ]:
            self.assertEqual(self.kinds(line), [], line)

    def test_each_kind_of_history_fails(self):
        cases = {
            "work-period": ["Since session 30 the default is 70 mm.", "sessions 6–8 ran it",
                            "the session's starting build", "measured in S12",
                            "on the CI machine of stop 25"],
            "ticket": ["as issue 37 asks", "issues 15 and 16", "fixed in #37",
                       "within the issue's 5 %", "see the ticket", "PR 12 added it"],
            "helper": ["shared with other agents' builds", "load from a helper's build"],
            "machine": ["on the Intel VM", "these VMs"],
            "commit": ["the build before (d4caf55)", "commit 5983814, 1221 s",
                       "`git show b9089a6:cases/x`"],
            "internal-file": ["as RULES.md says", "(../shared/peers.md)", "listed in the brief.",
                              "the BRIEF's figures", "Markauskas (seed 003)", "see notes.md",
                              "runs in /work/runs/x", "throwaway `/tmp` benchmarks"],
            "missing-path": ["see docs/validation/robustness.md", "cases/*/*_large.toml",
                             "app/trade_{command,table}.hpp"],
        }
        for kind, lines in cases.items():
            for line in lines:
                self.assertIn(kind, self.kinds(line), line)

    def test_phrases_that_only_look_like_history_pass(self):
        for line in [
            "the gate stops 2 s later; the solver stop 2 s after the door",
            "to issue a warning; small tensor helpers on Voigt vectors",
            "S355 steel, an S235 plate",
            "2.91422566e-01 and 0x9e3779b97f4a7c15 and colour #000000",
            "| `grainload run X` (5fff87849e03, ended 2026-12-05, 770 s on 1 thread) |",
            "its summaries record `604ef3f2e41a-dirty`",
            "`build/app/grainload run cases/silo/silo_small.toml --out /tmp/x`",
            "cases/*/*_small.toml and app/trade_{command,grid}.{hpp,cpp}",
            "cases/NAME/NAME_small.toml, cases/silo/silo.msh, build/bench/sph_throughput",
            "bench/sph_throughput prints it; io/version.hpp is configured",
        ]:
            self.assertEqual(self.kinds(line), [], line)
        # A CalculiX element in a page about CalculiX; outside one, S4 reads as a work period.
        self.assertEqual(self.kinds("ccx S4 shells, 16 x 16 S4"), [])
        self.assertEqual(self.kinds("measured in S4"), ["work-period"])
        # A command example may name /tmp and /work; prose may not.
        fenced = "```sh\ngrainload run X --out /work/runs/x\n```\n"
        self.assertEqual(self.kinds(fenced), [])
        spanning = "run `grainload run cases/silo/silo_small.toml\n--out /tmp/x` first"
        self.assertEqual(self.kinds(spanning), [])
        # Code may use the system's scratch folder; an #include may name a generated header.
        self.assertEqual(self.kinds("// scratch files in /tmp\n#include \"io/gen.hpp\"",
                                    path="app/x.cpp"), [])

    def test_every_section_of_every_page_is_scanned(self):
        # No file, section or line of the tree is left out: a finding under any heading of
        # docs/performance.md is reported with its own line number.
        page = "# P\n\n## Estimate against the run\n\nsession 3\n\n## Next\n\nsession 4\n"
        findings = check_history.scan_text("docs/performance.md", page, self.tree)
        self.assertEqual([(n, k) for n, k, _ in findings], [(5, "work-period"), (9, "work-period")])

    def test_the_script_exits_1_on_a_finding_and_0_on_a_clean_tree(self):
        script = str(SCRIPTS / "check_history.py")
        with tempfile.TemporaryDirectory() as root:
            make_repo(root, {"docs/clean.md": "The default is 0.3 because it is stable.\n"})
            clean = subprocess.run([sys.executable, script, "--root", root],
                                   capture_output=True, text=True)
            self.assertEqual(clean.returncode, 0, clean.stdout + clean.stderr)
        with tempfile.TemporaryDirectory() as root:
            make_repo(root, {"docs/diary.md": "Intro.\nSince session 30 the default is X.\n"})
            diary = subprocess.run([sys.executable, script, "--root", root],
                                   capture_output=True, text=True)
            self.assertEqual(diary.returncode, 1)
            self.assertIn("docs/diary.md:2: work-period: session 30", diary.stdout)


if __name__ == "__main__":
    unittest.main()
