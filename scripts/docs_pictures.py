#!/usr/bin/python3
"""Regenerate the pictures of docs/validation/ from runs, with one command.

    scripts/docs_pictures.py [--only NAME,...] [--from DIR] [--runs DIR] [--max-minutes M]
                             [--threads N] [--grainload PATH] [--list]

Every picture of docs/validation/ is listed in scripts/docs_picture_list.py with the runs it
comes from (case file and --set overrides, a `grainload trade` sweep, or a trade table stored
beside the case) and the commands that draw it. For each picture asked for (--only: picture
names or shell patterns, e.g. 'hopper_wagon_*'; default all), each run is taken from --from
DIR/<run> when a completed run is stored there, else from RUNS/<run> (default out/docs_runs)
when a completed one is there, else it is run into RUNS/<run> (`grainload run CASE --set ...
--out RUNS/<run>`), unless its measured wall time exceeds --max-minutes: then the picture is
left as it is and the command that would make it is printed. The pictures are then drawn into
docs/validation/, and docs/validation/pictures.md, the pictures' record, gets a row per picture
drawn: the case files, the run commands, the commit of the binary that ran them (summary.json's
git_hash), the date the run ended and its wall time. Rows of pictures not drawn stay as they
were. --list prints the pictures and their runs without running anything.

The expensive runs (the full wagon, the circular silo at its finer spacings, the 2D collapse's
aspect-ratio sweep) take 20 to 30 minutes each on a 2-core machine; the small cases seconds to
minutes. The build and the
packages come from scripts/build.sh, as for scripts/run.sh.
"""

import argparse
import datetime
import fnmatch
import json
import os
import shlex
import shutil
import subprocess
import sys

from docs_picture_list import PICTURES, RUNS

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DOCS = "docs/validation"
RECORD = os.path.join(DOCS, "pictures.md")
RECORD_HEAD = """# Where the validation pictures come from

Written by `scripts/docs_pictures.py` (docs/user-guide.md, "Pictures for reports"): one row per
picture of this folder, with the case files and commands of the runs it was drawn from, the
commit the runs' binary was built from (`git_hash` of their summary.json), the date each run
ended and its wall time. A picture drawn from a trade table names the table; its runs' dates
are in the table's page. Regenerate one picture with
`scripts/docs_pictures.py --only NAME`, all of them with `scripts/docs_pictures.py`.

| picture | page | drawn from | runs (commit, ended, wall time) |
| --- | --- | --- | --- |
"""


def run_command(run_id, run, grainload, folder, threads):
    """The command line that makes the run (argv)."""
    if run.kind == "script":
        return ["/usr/bin/python3" if a == "python" else fill(a, {"grainload": grainload,
                                                                   "self": folder})
                for a in run.arguments]
    verb = "trade" if run.kind == "trade" else "run"
    command = [grainload, verb, run.case]
    for item in run.sets:
        command += ["--set", item]
    command += run.arguments + ["--out", folder, "--threads", str(threads)]
    return command


def shown(command):
    """A command as a user types it (python for /usr/bin/python3)."""
    return " ".join(shlex.quote(a) for a in command).replace("/usr/bin/python3", "python3")


def fill(text, folders):
    for key, value in folders.items():
        text = text.replace("{" + key + "}", value)
    return text


def same_overrides(given, wanted):
    """Whether a run's --set overrides are the list's (quotes and spaces aside)."""
    def plain(items):
        return [i.replace('"', "").replace("'", "").replace(" ", "") for i in items]
    return plain(given) == plain(wanted)


def is_complete(folder, run):
    """Whether the folder holds the run, completed, with the list's overrides."""
    path = os.path.join(folder, run.done)
    if not os.path.isfile(path):
        return False
    if run.done != "summary.json":
        return True
    try:
        with open(path) as f:
            summary = json.load(f)
    except ValueError:
        return False
    if not same_overrides(summary.get("overrides", []), run.sets):
        print(f"docs_pictures: {folder} was run with other overrides; not used")
        return False
    return summary.get("status") == "completed"


def find_run(run_id, run, args):
    """The folder of a completed run: stored (--from), made before (--runs), or None."""
    for base in ([args.stored] if args.stored else []) + [args.runs]:
        folder = os.path.join(base, run_id)
        if is_complete(folder, run):
            return folder
    return None


def make_run(run_id, run, args):
    folder = os.path.join(args.runs, run_id)
    command = run_command(run_id, run, args.grainload, folder, args.threads)
    os.makedirs(folder, exist_ok=True)
    print(f"docs_pictures: running {run_id} (about {run.minutes:g} min here): {shown(command)}",
          flush=True)
    with open(folder + ".log", "w") as log:
        code = subprocess.call(command, stdout=log, stderr=subprocess.STDOUT, cwd=ROOT)
    if not is_complete(folder, run):
        print(f"docs_pictures: {run_id} did not complete (exit {code}); see {folder}.log")
        return None
    return folder


def provenance(run_id, run, folder, threads):
    """'the command, commit, date, wall time' of a run, for the record."""
    summary_path = os.path.join(folder, "summary.json")
    if run.kind != "run" or not os.path.isfile(summary_path):
        case = shown(run_command(run_id, run, "grainload", folder, threads))
        ended = datetime.date.fromtimestamp(os.path.getmtime(os.path.join(folder, run.done)))
        return f"`{case}` (ended {ended})"
    with open(summary_path) as f:
        summary = json.load(f)
    case = shown(run_command(run_id, run, "grainload", folder, summary.get("threads", "N")))
    ended = datetime.date.fromtimestamp(os.path.getmtime(summary_path))
    threads = summary.get("threads", "?")
    return (f"`{case}` ({summary.get('git_hash', '?')}, ended {ended}, "
            f"{summary.get('wall_time_s', 0.0):.0f} s on {threads} "
            f"thread{'' if threads == 1 else 's'})")


def draw(picture, folders, args):
    """Runs the picture's drawing commands; True when every one succeeded."""
    for step in picture.draw:
        step = [fill(a, folders) for a in step]
        if step[0] == "copy":
            shutil.copyfile(step[1], step[2])
            continue
        prefix = {"python": ["/usr/bin/python3"],
                  "xvfb": ["xvfb-run", "-a", "/usr/bin/python3"]}[step[0]]
        result = subprocess.run(prefix + step[1:], cwd=ROOT, capture_output=True, text=True)
        if result.returncode != 0:
            print(f"docs_pictures: drawing {picture.files[0]} failed: {shown(prefix + step[1:])}"
                  f"\n{result.stdout[-2000:]}{result.stderr[-2000:]}")
            return False
    return True


def read_record():
    rows = {}
    if os.path.isfile(RECORD):
        for line in open(RECORD):
            if line.startswith("| `") or line.startswith("| ["):
                name = line.split("|")[1].strip().strip("`[]").split("]")[0]
                rows[name] = line.rstrip("\n")
    return rows


def write_record(rows):
    with open(RECORD, "w") as f:
        f.write(RECORD_HEAD)
        for name in sorted(rows):
            f.write(rows[name] + "\n")


def record_row(picture, name, sources, folders):
    folders = dict(folders, grainload="grainload")  # the command as a user types it
    drawn = "; ".join(f"`{shown([fill(a, folders) for a in s])}`"
                      for s in picture.draw if s[0] != "copy")
    drawn = drawn.replace("`xvfb ", "`xvfb-run -a python3 ").replace("`python ", "`python3 ")
    return f"| [{name}]({name}) | [{picture.page}]({picture.page}) | {drawn} | {sources} |"


def selected(args):
    patterns = [p for p in (args.only or "").split(",") if p]
    chosen = []
    for picture in PICTURES:
        if not patterns or any(fnmatch.fnmatch(os.path.splitext(f)[0], p) or fnmatch.fnmatch(f, p)
                               for f in picture.files for p in patterns):
            chosen.append(picture)
    return chosen


def list_pictures(pictures, args):
    for picture in pictures:
        print(", ".join(picture.files) + f"  ({DOCS}/{picture.page})")
        if picture.table:
            print(f"    from the stored trade table {picture.table}")
        for run_id in picture.runs:
            run = RUNS[run_id]
            found = find_run(run_id, run, args)
            if found:
                print(f"    {run_id}: completed in {found}")
                continue
            folder = os.path.join(args.runs, run_id)
            print(f"    {run_id}: about {run.minutes:g} min: "
                  f"{shown(run_command(run_id, run, args.grainload, folder, args.threads))}")


def regenerate(pictures, args):
    """Draws every picture whose runs are at hand or affordable; returns what was left out."""
    record, left = read_record(), []
    folders = {"docs": DOCS, "grainload": args.grainload}
    for picture in pictures:
        missing = []
        for run_id in picture.runs:
            run = RUNS[run_id]
            if run_id in folders:
                continue
            folder = find_run(run_id, run, args)
            if folder is None and (args.max_minutes is None or run.minutes <= args.max_minutes):
                folder = make_run(run_id, run, args)
            if folder is None:
                missing.append(run_id)
            else:
                folders[run_id] = folder
        if missing:
            left.append((picture, missing))
            continue
        if not draw(picture, folders, args):
            left.append((picture, []))
            continue
        sources = (f"the stored table `{picture.table}`" if picture.table else
                   "; ".join(provenance(r, RUNS[r], folders[r], args.threads)
                             for r in picture.runs))
        for name in picture.files:
            record[name] = record_row(picture, name, sources, folders)
            print(f"docs_pictures: {DOCS}/{name} <- {sources}")
    write_record(record)
    return left


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--only", help="picture names or patterns, comma-separated")
    parser.add_argument("--from", dest="stored", help="a folder of stored runs (one per run)")
    parser.add_argument("--runs", default="out/docs_runs", help="where runs are made")
    parser.add_argument("--max-minutes", type=float, help="run nothing measured to take longer")
    parser.add_argument("--threads", default="2")
    parser.add_argument("--grainload", help="the executable (default: build it)")
    parser.add_argument("--list", action="store_true", help="list the pictures and their runs")
    args = parser.parse_args(argv)
    os.chdir(ROOT)
    pictures = selected(args)
    if not pictures:
        print(f"docs_pictures: no picture matches {args.only}")
        return 2
    if args.list:
        args.grainload = args.grainload or "build/app/grainload"
        list_pictures(pictures, args)
        return 0
    if args.grainload is None:
        subprocess.check_call(["bash", "scripts/build.sh", "--target", "grainload"])
        args.grainload = os.path.join(os.environ.get("GRAINLOAD_BUILD", "build"), "app",
                                      "grainload")
    left = regenerate(pictures, args)
    for picture, missing in left:
        why = ("needs " + ", ".join(f"{r} (about {RUNS[r].minutes:g} min)" for r in missing)
               if missing else "drawing failed")
        print(f"docs_pictures: not regenerated: {', '.join(picture.files)}: {why}")
        for run_id in missing:
            folder = os.path.join(args.runs, run_id)
            print("    " + shown(run_command(run_id, RUNS[run_id], args.grainload, folder,
                                             args.threads)))
    return 1 if left else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
