"""What the tests of grainload's tree checks share: a temporary source tree made of given files,
and a check script run on a tree."""

import pathlib
import subprocess
import sys
import tempfile


def run(script, root):
    """`script` (a path) on the tree at `root`: its exit code and what it printed."""
    result = subprocess.run([sys.executable, "-B", str(script), str(root)],
                            capture_output=True, text=True, check=False)
    return result.returncode, result.stdout


def tree(files):
    """A temporary source tree holding `files` (path: text)."""
    folder = tempfile.TemporaryDirectory()
    for path, text in files.items():
        target = pathlib.Path(folder.name) / path
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(text, encoding="utf-8")
    return folder
