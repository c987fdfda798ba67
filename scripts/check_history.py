#!/usr/bin/python3
"""Checks that the repository speaks of the product, not of how it was made.

    scripts/check_history.py [--root DIR] [--summary]

Scans every file git tracks (`git ls-files`) as text and prints `file:line: kind: what` for
each finding; exits 1 if there is any, 0 otherwise. --summary adds the count per kind.

Skipped: binary files (a NUL byte or not UTF-8), pictures (.png, .jpg, .svg), and data that
programs write (.csv trade tables, .msh and .stl meshes, .k keyword decks, .pyc, the fuzzers'
regression inputs under tests/fuzz/regressions/), and this script and its test, which quote
what they forbid. CHANGELOG.md is scanned like any file: it may name versions, never sessions
or tickets.

The kinds, each a precise rule (what a newcomer's page may not say):

  work-period   a numbered period of work: "session 12", "sessions 6-8", "session-31", "sprint 3",
                "stop 25" (not "stop 2 s": a number with a unit is a quantity), "S12"; and
                "session" itself (this session, the session's build). An "S" with one or two
                digits is a CalculiX shell element (S3, S4, S6, S8) only in a file that names
                CalculiX or ccx.
  ticket        a ticket: "issue 37", "issues 15 and 16", "issue-20", "#37" (1-5 digits after a
                space or bracket), "ticket", "PR 12", "MR 3", "pull request", the noun "issue" with
                an article or possessive ("the issue's 5 %"); the verb ("to issue a warning")
                is not one.
  helper        a person working on the code: "agent(s)", "the/a/another helper", "helper's";
                "tensor helpers" and "Helpers of the tests" (code) are not.
  machine       a virtual machine: "VM", "VMs", "virtual machine". Name the processor instead
                ("a 2-core AMD EPYC").
  commit        a commit hash: 7-40 lower-case hex digits with at least one letter and one
                digit, standing alone (not part of a number such as 2.91422566e-01, not 0x...),
                or digits alone after "commit", "build", "git" or "HEAD" (commit 5983814).
                Allowed only where the product writes it as a record: `HASH-dirty` or
                "(HASH, ended DATE" as scripts/docs_pictures.py writes docs/validation/pictures.md
                from summary.json's git_hash.
  internal-file a file of the workplace, not of the product: RULES.md, BRIEF.md, "the brief",
                "BRIEF", anything under shared/ or ../shared/, a source file of the workplace's
                library ("seed 003", seeds/001_*), a `NAME.md` whose name no tracked file has;
                an absolute path under /work/ anywhere but in a command example, and one under
                /tmp in a Markdown page's prose. A command example is a fenced code block of a
                Markdown page, or an inline code span holding a command (a space inside, or
                running over a line break). Code and comments outside Markdown may use /tmp
                (the system's scratch folder).
  missing-path  a path starting with a top-level folder of the tree (app/, docs/, cases/, ...)
                that names nothing tracked, anywhere but in an #include (the compiler checks
                those, and they may name a generated header). Globs (`cases/*/*_small.toml`)
                and braces (`app/trade/trade_{command,grid}.{hpp,cpp}`) are expanded and must match
                something; an upper-case word (`cases/NAME/NAME_small.toml`) or <...> is a
                placeholder. Not missing: a path git ignores (a mesh a .geo makes, build/, out/:
                a product of a run or a build), a name without its suffix (`bench/sph_throughput`:
                a program or module), a file whose NAME.in is tracked (io/version.hpp: a file
                the build configures).

A finding is fixed by saying it in product language: a figure's source is a paper, a standard
or a measurement (the command and the machine), not the period in which it was taken.
"""

import argparse
import os
import re
import subprocess
import sys
from collections import Counter


SKIPPED_SUFFIXES = (".png", ".jpg", ".jpeg", ".gif", ".svg", ".pdf", ".csv", ".msh", ".stl",
                    ".k", ".pyc", ".vtu", ".vtm", ".bin")
SKIPPED_FOLDERS = ("tests/fuzz/regressions/",)
# The rules' own definition and test quote what they forbid.
SKIPPED_FILES = ("scripts/check_history.py", "tests/unit/scripts/test_check_history.py")

NUMBER_LIST = r"(?:\s*(?:[-–,]|and|to)\s*\d+(?![\d.]))*"
WORK_PERIOD = [
    re.compile(r"\b(?:sessions?|sprints?)[ -]\d+" + NUMBER_LIST, re.I),
    re.compile(r"\bstop[ -]\d+(?![\d.])(?!\s*(?:s|ms|min|h|m|mm|cm|%|steps?)\b)" + NUMBER_LIST,
               re.I),
    re.compile(r"\bsessions?\b(?:'s|s')?", re.I),
    re.compile(r"\bwork periods?\b", re.I),
]
S_NUMBER = re.compile(r"(?<![\w.])S\d{1,2}\b")
CALCULIX_ELEMENT = re.compile(r"^S[3468]$")
CALCULIX_FILE = re.compile(r"calculix|\bccx\b", re.I)

TICKET = [
    re.compile(r"\b(?:issues?|tickets?|pull requests?)[ -]?#?\d+" + NUMBER_LIST, re.I),
    re.compile(r"\b(?:PR|MR)s?[ -]?#?\d+" + NUMBER_LIST),
    re.compile(r"(?<![\w&#/])#\d{1,5}(?![\w])"),
    re.compile(r"\btickets?\b|\bpull requests?\b", re.I),
    # The noun: with an article, a possessive, or a colon after it; not the verb "to issue".
    re.compile(r"\b(?:the|this|that|an?|later|earlier|silo|each)\s+issue\b|\bissue(?:'s|s'|:)",
               re.I),
]

HELPER = [
    re.compile(r"\bagents?\b(?:'s|')?", re.I),
    re.compile(r"\b(?:the|a|another|other|each|one)\s+helpers?\b(?!\s+(?:function|class|of)\b)"
               r"|\bhelpers?'s?(?=\s)", re.I),
]

MACHINE = [re.compile(r"\bVMs?\b"), re.compile(r"\bvirtual machines?\b", re.I)]

HASH = re.compile(r"(?<![\w.+\-/#])(?<!0x)([0-9a-f]{7,40})(?![\w])")
# A number after "commit", "build", "git" or "HEAD" is a hash even without a letter (5983814).
HASH_NAMED = re.compile(
    r"\b(?:commits?|builds?|git|HEAD|main at|tree of)\s+`?([0-9a-f]{7,40})(?![\w])", re.I)
HASH_RECORD_AFTER = re.compile(r"-dirty|, ended \d{4}-\d{2}-\d{2}")

INTERNAL = [
    re.compile(r"\b(?:RULES|BRIEF|STYLE_ANCHORS)\.md\b"),
    re.compile(r"\bBRIEF\b"),
    re.compile(r"\bthe brief(?='s|\s*[),.;:]|\s*$)", re.I),
    re.compile(r"(?<![\w/.-])(?:\.\./)*shared/[\w./*-]*"),
    re.compile(r"\bseeds?[\s/`]*0\d\d(?!\d)[\w*.]*`?", re.I),
]
MARKDOWN_NAME = re.compile(r"(?<![\w./-])([\w-]+\.md)\b")
ABSOLUTE_WORK = re.compile(r"(?<![\w.])/work/[\w./*{},-]*")
ABSOLUTE_TMP = re.compile(r"(?<![\w.])/tmp\b[\w./*-]*")

INCLUDE = re.compile(r"\s*#\s*include\b")
PATH_START = r"(?<![\w./@:-])(?:{folders})/"
# A placeholder in a path: an upper-case word (NAME, CASE) or <...>.
PLACEHOLDER = re.compile(r"(?<![A-Za-z])[A-Z][A-Z0-9]+(?![a-z])|<[^<>/]*>")


def git_files(root):
    out = subprocess.run(["git", "-C", root, "ls-files", "-z"], check=True,
                         capture_output=True).stdout
    return [p for p in out.decode().split("\0") if p]


class Tree:
    """The tracked files and their folders; what git ignores counts as a run's product."""

    def __init__(self, root, files):
        self.root = root
        self.files = set(files)
        self.folders = set()
        for path in files:
            parts = path.split("/")
            for i in range(1, len(parts)):
                self.folders.add("/".join(parts[:i]))
        self.top = sorted({p.split("/")[0] for p in files if "/" in p and not p.startswith(".")})
        self.basenames = {os.path.basename(p) for p in files}
        self._ignored = {}

    def exists(self, path):
        path = path.rstrip("/")
        return path in self.files or path in self.folders

    def matches(self, pattern):
        regex = re.compile(glob_regex(pattern.rstrip("/")))
        return any(regex.fullmatch(p) for p in self.files | self.folders)

    def product(self, path):
        """A program or module named without its suffix (`bench/sph_throughput`, the source
        bench/sph_throughput.cpp), a file a tracked template `NAME.in` configures
        (io/version.hpp from cmake/version.hpp.in), or something git ignores."""
        if any(f.startswith(path + ".") and "/" not in f[len(path):] for f in self.files):
            return True
        if os.path.basename(path) + ".in" in self.basenames:
            return True
        return self.ignored(path)

    def ignored(self, path):
        if path not in self._ignored:
            result = subprocess.run(["git", "-C", self.root, "check-ignore", "-q", "--no-index",
                                     path], capture_output=True)
            self._ignored[path] = result.returncode == 0
        return self._ignored[path]


def glob_regex(pattern):
    """A shell glob as a regex: * and ? within one segment, ** across segments."""
    out = []
    i = 0
    while i < len(pattern):
        if pattern.startswith("**", i):
            out.append(".*")
            i += 2
        elif pattern[i] == "*":
            out.append("[^/]*")
            i += 1
        elif pattern[i] == "?":
            out.append("[^/]")
            i += 1
        else:
            out.append(re.escape(pattern[i]))
            i += 1
    return "".join(out)


def expand_braces(text):
    """`a_{b,c}.{h,cpp}` -> a_b.h, a_b.cpp, a_c.h, a_c.cpp."""
    match = re.search(r"\{([^{}]*)\}", text)
    if not match:
        return [text]
    out = []
    for option in match.group(1).split(","):
        out.extend(expand_braces(text[:match.start()] + option + text[match.end():]))
    return out


def path_tokens(line, tree):
    """Path-like tokens starting with a top-level folder, with their column."""
    start = re.compile(PATH_START.format(folders="|".join(map(re.escape, tree.top))))
    for match in start.finditer(line):
        end = match.end()
        depth = 0
        while end < len(line):
            c = line[end]
            if c == "{":
                depth += 1
            elif c == "}" and depth:
                depth -= 1
            elif not (c.isalnum() or c in "_./*?-+" or (c == "," and depth)):
                break
            end += 1
        token = line[match.start():end].rstrip(".-")
        yield match.start(), token


def path_missing(token, tree):
    """The first of the token's expansions that names nothing, or None."""
    for candidate in expand_braces(token):
        candidate = candidate.rstrip("/")
        if tree.exists(candidate) or tree.product(candidate):
            continue
        pattern = PLACEHOLDER.sub("*", candidate)
        if not (("*" in pattern or "?" in pattern) and tree.matches(pattern)):
            return candidate
    return None


def code_spans(line, open_span):
    """Markdown inline code spans of one line as (start, end, is_command), and whether a span
    is left open at its end. A span may run over lines: `open_span` says one is open at the
    start. A span is a command when it holds a space or runs over a line break."""
    spans = []
    ticks = [i for i, c in enumerate(line) if c == "`"]
    start = 0 if open_span else None
    for i in ticks:
        if start is None:
            start = i
        else:
            text = line[start:i]
            spans.append((start, i + 1, " " in text.strip("` ") or start == 0 and open_span))
            start = None
    if start is not None:
        spans.append((start, len(line), True))
    return spans, start is not None


def in_command_span(column, spans):
    return any(a <= column < b and command for a, b, command in spans)


def scan_line(path, line, tree, markdown, fenced, calculix_file, spans=()):
    """The findings of one line: (kind, text)."""
    found = []
    for rule in WORK_PERIOD:
        found += [("work-period", m.group(0)) for m in rule.finditer(line)]
    for m in S_NUMBER.finditer(line):
        if not (CALCULIX_ELEMENT.match(m.group(0)) and calculix_file):
            found.append(("work-period", m.group(0)))
    for rule in TICKET:
        found += [("ticket", m.group(0)) for m in rule.finditer(line)]
    for rule in HELPER:
        found += [("helper", m.group(0)) for m in rule.finditer(line)]
    for rule in MACHINE:
        found += [("machine", m.group(0)) for m in rule.finditer(line)]
    for m in HASH.finditer(line):
        text = m.group(1)
        if not (re.search(r"[a-f]", text) and re.search(r"\d", text)):
            continue
        if re.fullmatch(r"\d+e\d+", text) or HASH_RECORD_AFTER.match(line, m.end()):
            continue
        found.append(("commit", text))
    for m in HASH_NAMED.finditer(line):
        if not re.search(r"[a-f]", m.group(1)):
            found.append(("commit", m.group(1)))
    for rule in INTERNAL:
        found += [("internal-file", m.group(0)) for m in rule.finditer(line)]
    for m in MARKDOWN_NAME.finditer(line):
        if m.group(1) not in tree.basenames:
            found.append(("internal-file", m.group(1)))
    for m in ABSOLUTE_WORK.finditer(line):
        if not (fenced or in_command_span(m.start(), spans)):
            found.append(("internal-file", m.group(0)))
    if markdown and not fenced:
        for m in ABSOLUTE_TMP.finditer(line):
            if not in_command_span(m.start(), spans):
                found.append(("internal-file", m.group(0)))
    if INCLUDE.match(line):
        return dedupe(found)  # the compiler checks an include; it may name a generated header
    for column, token in path_tokens(line, tree):
        missing = path_missing(token, tree)
        if missing:
            found.append(("missing-path", token))
    return dedupe(found)


def dedupe(found):
    """One finding per overlapping text: the longest of each kind."""
    out = []
    for kind, text in sorted(found, key=lambda f: -len(f[1])):
        if not any(k == kind and text in t for k, t in out):
            out.append((kind, text))
    return out


def scan_text(path, text, tree):
    """(line, kind, text) of every finding in one file's text."""
    markdown = path.endswith(".md")
    calculix_file = bool(CALCULIX_FILE.search(text))
    lines = text.split("\n")
    fenced = False
    open_span = False
    findings = []
    for number, line in enumerate(lines, 1):
        if markdown and line.lstrip().startswith("```"):
            fenced = not fenced
            continue
        spans = []
        if markdown and not fenced:
            open_span = open_span and bool(line.strip())  # a blank line ends a paragraph
            spans, open_span = code_spans(line, open_span)
        for kind, what in scan_line(path, line, tree, markdown, fenced, calculix_file, spans):
            findings.append((number, kind, what))
    return findings


def read_text(full_path):
    with open(full_path, "rb") as f:
        data = f.read()
    if b"\0" in data:
        return None
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        return None


def scanned(path):
    if path in SKIPPED_FILES:
        return False
    return not (path.lower().endswith(SKIPPED_SUFFIXES) or path.startswith(SKIPPED_FOLDERS))


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--root", default=os.path.dirname(os.path.dirname(
        os.path.abspath(__file__))), help="the repository (default: this script's)")
    parser.add_argument("--summary", action="store_true", help="print the count per kind")
    args = parser.parse_args(argv)
    files = git_files(args.root)
    tree = Tree(args.root, files)
    counts = Counter()
    for path in files:
        full = os.path.join(args.root, path)
        if not scanned(path) or not os.path.isfile(full):
            continue
        text = read_text(full)
        if text is None:
            continue
        for number, kind, what in scan_text(path, text, tree):
            print(f"{path}:{number}: {kind}: {what}")
            counts[kind] += 1
    if args.summary or counts:
        total = sum(counts.values())
        detail = ", ".join(f"{k} {n}" for k, n in sorted(counts.items()))
        print(f"check_history: {total} finding(s){': ' + detail if detail else ''}",
              file=sys.stderr)
    return 1 if counts else 0


if __name__ == "__main__":
    sys.exit(main())
