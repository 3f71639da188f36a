#!/usr/bin/env python3
"""Every command a user could copy from README.md, docs/*.md and the comments of
scenes/*.toml, run at a CPU size (docs/reliability.md, "Documented commands").

What counts as a command:
  - a fenced block tagged sh, bash, shell or console: every line (lines joined
    at a trailing backslash; for/if/while ... done/fi as one; a "$ " prompt
    dropped); in an untagged block, the lines that begin with "$ " or with a
    program this test knows (PROGRAMS); a python block is one snippet;
  - an inline `code span` that begins with a program this test knows and says
    more than its name (`arnoldweb run` names a command, `arnoldweb run
    scenes/x.toml` is one). A span with a placeholder (SCENE, OUT, <dir>, ...)
    is a form, not a command;
  - in a scene's comments, a line that begins with a program (with its
    continuation lines, indented, beginning with --), less a closing remark in
    parentheses ("(CPU size)").

How it runs (see tests/docs/rules.toml for the tables):
  - each block (or span, or a scene comment's command) in a fresh sandbox: a copy
    of scenes/, bench/, scripts/, examples/ and the docs' text, build/ linked to
    this build and tests/ to the repository's; `arnoldweb` on PATH is this
    build's CLI;
  - at CI size, every `arnoldweb run|accuracy` of a scene (and `bench --scene`)
    gets the scene's CI size from rules.toml: its scale (trajectories, map
    resolution) over the command's, its durations and intervals where the
    command gives none; markers add to that;
  - a path under /tmp/ is one under the sandbox's tmp/;
  - a device this machine lacks (cuda:N without a GPU) becomes cpu; run.device
    "auto" is the cpu backend (ARNOLDWEB_DEVICE=cpu);
  - the command must exit 0 (or as its marker says), and a run must leave a
    summary.json written after it started.

Markers: an HTML comment before the block or span, or a "# docs-test:" comment
line in a scene before the command:
    <!-- docs-test: set ensemble.trajectories=2000 run.duration=5 -->
one directive a line; "[text]" in front limits a directive to the commands
that contain text ("[^text]": that begin with it; of skip, full and ci the
first that matches decides); "ci" in front applies it at CI size only (set
always is).
    set K=V ...          --set K=V on each arnoldweb run/check/continue/accuracy (CI size)
    args ARGS            ARGS appended to the command
    replace "A" "B"      A replaced by B in the command's text
    before: CMD          CMD run first, in the same sandbox (at the same size)
    exit N               the exit status expected (default 0)
    creates PATH ...     files the command leaves (relative to the sandbox)
    timeout S            seconds (default 300 at CI size, --timeout)
    skip: REASON         never run here (a GPU machine, Slurm, a peer's library)
    full: REASON         run only with --full (the commands as written)
    ci: FILE             CI runs it elsewhere: FILE (which must name the command's program)
    python               for the python suite (automatic for python and pip commands)
    apart                each command in a sandbox of its own (a list of examples, not a sequence)
A marker that applies to nothing, a "[text]" that matches no command, a run of
a scene without a CI size and a command with a placeholder left ("...", <x>)
fail the test: a command is run unless a marker or a rule says why not.

    tests/docs/doc_commands.py --cli build/arnoldweb            CI size, every shell command
    tests/docs/doc_commands.py --cli build/arnoldweb --full     as written (hours; GPU jobs)
    tests/docs/doc_commands.py --list                            what would run, and how
    tests/docs/doc_commands.py --cli ... -k frequencies          the commands whose source or text has it
The python suite (tests/python/test_doc_commands.py) runs the python ones
with the test environment's python (`--python PATH` runs them here).
"""
from __future__ import annotations

import argparse
import concurrent.futures
import dataclasses
import glob
import os
import re
import textwrap
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
import time

try:
    import tomllib
except ImportError:  # Python < 3.11
    print("doc_commands: SKIPPED: needs Python 3.11 or newer (tomllib)")
    sys.exit(1 if os.environ.get("ARNOLDWEB_REQUIRE_CHECKS") == "1" else 77)

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.realpath(__file__))))
RULES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "rules.toml")

# Programs a command may begin with (after NAME=value assignments).
PROGRAMS = re.compile(
    r"^(arnoldweb|build/\S+|scripts/\S+\.sh|bench/\S+\.(?:sh|py)|examples/\S+\.py|\.\./shared/\S+|"
    r"python3?|/usr/bin/python3|pip3?|bash|mpirun|srun|sbatch|ctest|cmake|ninja|ncu|nsys|"
    r"/usr/bin/time|kill|cp|ls|cd|h5dump|for|if|while)$")
PYTHON = re.compile(r"^(python3?|/usr/bin/python3|pip3?|\S+\.py)$")
COMPOUND = re.compile(r"^(for \w+ in .*; do|if .*; then|while .*; do)$")
ENV = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*=")
# arnoldweb subcommands that need an argument: the name alone is a reference
NEEDS_ARGUMENT = {"run", "check", "resume", "continue", "compare", "render", "accuracy"}
# options of arnoldweb that take a value (to find the positional argument)
VALUE_OPTIONS = {"--device", "-d", "--set", "-s", "--out", "-o", "--for", "--target", "--alpha", "--what",
                 "--min-count", "--preset", "--devices", "--sizes", "--steps", "--precision", "--scene",
                 "--memory", "--repeat", "--variants"}
PLACEHOLDER = re.compile(r"(<[^>]*>|\.\.\.|…|(?:^|[\s=])[A-Z][A-Z0-9_]*(?=$|[\s,]))")
MARKER = re.compile(r"<!--\s*docs-test:(.*?)-->", re.S)
SHELL_LANGS = {"sh", "bash", "shell", "console"}


class DocError(Exception):
    """A documented command the test cannot take as it is: a marker to add or fix."""


# ---------------------------------------------------------------- directives

@dataclasses.dataclass
class Directive:
    verb: str
    value: str
    scope: str = ""        # "" for every command of the element
    ci_only: bool = False
    used: bool = False

    def applies(self, text: str) -> bool:
        if self.scope.startswith("^"):
            return text.startswith(self.scope[1:])
        return not self.scope or self.scope in text


def parse_marker(text: str, where: str) -> list[Directive]:
    out = []
    for line in text.strip().splitlines():
        line = line.strip()
        if not line:
            continue
        scope = ""
        if line.startswith("["):
            end = line.index("]")
            scope, line = line[1:end], line[end + 1:].strip()
        ci_only = False
        if line.startswith("ci ") and not line.startswith("ci:"):
            ci_only, line = True, line[3:].strip()
        m = re.match(r"^(set|args|replace|before:|exit|creates|timeout|skip:|full:|ci:|python|apart)\s*(.*)$", line)
        if not m:
            raise DocError(f"{where}: docs-test marker: cannot read {line!r} (docs/reliability.md lists the directives)")
        verb = m.group(1).rstrip(":")
        out.append(Directive(verb, m.group(2).strip(), scope, ci_only or verb == "set"))
    return out


# ---------------------------------------------------------------- extraction

@dataclasses.dataclass
class Command:
    text: str
    line: int


@dataclasses.dataclass
class Element:
    path: str              # relative to the repository
    line: int
    what: str              # "block", "span", "scene comment"
    commands: list[Command]
    directives: list[Directive]
    python_code: bool = False   # a python block: one snippet

    @property
    def where(self) -> str:
        return f"{self.path}:{self.line}"

    @property
    def is_python(self) -> bool:
        return self.python_code or any(d.verb == "python" for d in self.directives) or any(
            PYTHON.match(program_of(c.text)) for c in self.commands)


def words_after_env(text: str) -> list[str]:
    try:
        words = shlex.split(text, comments=True)
    except ValueError:
        words = text.split()
    while words and ENV.match(words[0]):
        words = words[1:]
    return words


def program_of(text: str) -> str:
    words = words_after_env(text.lstrip("$ ").strip())
    return words[0] if words else ""


def is_command_start(text: str) -> bool:
    t = text.strip()
    if t.startswith("$ "):
        return True
    words = t.split()
    while words and ENV.match(words[0]):
        words = words[1:]
    if not words:  # assignments alone, continued on the next line
        return t.endswith("\\") and ENV.match(t) is not None
    if words[0] in {"for", "if", "while"}:
        return COMPOUND.match(t) is not None
    return PROGRAMS.match(words[0]) is not None


def logical_lines(lines: list[tuple[int, str]], every_line: bool) -> list[Command]:
    """Commands of a block: continuation lines joined, compound commands whole."""
    out: list[Command] = []
    i = 0
    while i < len(lines):
        number, text = lines[i]
        stripped = text.strip()
        i += 1
        if stripped.startswith("$ "):
            stripped = stripped[2:]
        elif not stripped or stripped.startswith("#") or not (every_line or is_command_start(stripped)):
            continue
        parts = [stripped]
        depth = 1 if COMPOUND.match(stripped) else 0
        while (parts[-1].endswith("\\") or depth > 0) and i < len(lines):
            nxt = lines[i][1].strip()
            i += 1
            if COMPOUND.match(nxt):
                depth += 1
            if re.match(r"^(done|fi)\b", nxt):
                depth -= 1
            parts.append(nxt)
        out.append(Command("\n".join(parts), number))
    return out


def strip_comments(text: str) -> str:
    return MARKER.sub(lambda m: " " * len(m.group(0)), re.sub(r"<!--(?!\s*docs-test:).*?-->",
                                                                  lambda m: re.sub(r"[^\n]", " ", m.group(0)),
                                                                  text, flags=re.S))


def inline_command(span: str) -> str | None:
    """The command of an inline code span, or None for a name, a form or not a command."""
    text = " ".join(span.split())
    words = text.split()
    while words and ENV.match(words[0]):
        words = words[1:]
    if not words or not PROGRAMS.match(words[0]) or words[0] in {"for", "if", "while", "cd", "ls", "kill", "cp"}:
        return None
    if len(words) == 1:
        return None  # a program's name
    if words[0] in {"arnoldweb", "build/arnoldweb"} and len(words) == 2:
        return None  # `arnoldweb bench`: a command named
    if words[0] in {"arnoldweb", "build/arnoldweb"} and words[1] in NEEDS_ARGUMENT:
        rest, k = words[2:], 0
        positional = False
        while k < len(rest):
            if rest[k] in VALUE_OPTIONS:
                k += 2
                continue
            if not rest[k].startswith("-"):
                positional = True
            k += 1
        if not positional:
            return None  # `arnoldweb run --out`: a command and an option named
    if words[0] in {"mpirun", "srun"} and not any(PROGRAMS.match(w) for w in words[1:]):
        return None  # `mpirun -n 2`: the launcher named
    if words[:2] == ["pip", "install"] and len(words) == 2:
        return None
    if PYTHON.match(words[0]) and (all(w.startswith("-") for w in words[1:]) or
                                   (words[1] == "-m" and len(words) == 3)):
        return None  # `python -c`, `python -m arnoldweb`, `python3 -m venv`: named, not given
    if PLACEHOLDER.search(text) or re.search(r"\$[A-Za-z_{(]", text):
        return None  # a form with placeholders
    return text


def markdown_elements(path: str) -> list[Element]:
    rel = os.path.relpath(path, ROOT)
    lines = open(path, encoding="utf-8").read().split("\n")
    # the fenced blocks; the prose is the text outside them, line for line
    events: list[tuple[int, int, str, object]] = []  # (line, column, kind, payload), in document order
    prose: list[str] = []
    block: list[tuple[int, str]] | None = None
    for number, line in enumerate(lines, 1):
        if block is None and re.match(r"^\s*```", line):
            block, lang, start = [], line.strip()[3:].strip().lower(), number
            prose.append("")
        elif block is not None and line.strip().startswith("```"):
            events.append((start, 0, "block", (lang, block)))
            block = None
            prose.append("")
        elif block is not None:
            block.append((number, line))
            prose.append("")
        else:
            prose.append(line)
    text = "\n".join(prose)

    def position(offset: int) -> tuple[int, int]:
        line = text.count("\n", 0, offset) + 1
        return line, offset - (text.rfind("\n", 0, offset) + 1)

    for m in MARKER.finditer(text):
        events.append((*position(m.start()), "marker", m.group(1)))
    for m in re.finditer(r"(?<!`)`([^`]+)`(?!`)", strip_comments(text)):
        if command := inline_command(m.group(1)):
            events.append((*position(m.start()), "span", command))
    events.sort(key=lambda e: (e[0], e[1]))

    result: list[Element] = []
    pending: list[Directive] | None = None
    pending_at = 0
    for line, _, kind, payload in events:
        if kind == "marker":
            if pending is not None:
                raise DocError(f"{rel}:{pending_at}: docs-test marker applies to nothing (another marker follows)")
            pending, pending_at = parse_marker(payload, f"{rel}:{line}"), line
            continue
        element = None
        if kind == "span":
            element = Element(rel, line, "span", [Command(payload, line)], [])
        else:
            lang, block = payload
            if lang == "python":
                element = Element(rel, line, "block",  # a block in a list item: its indent is the item's
                                  [Command(textwrap.dedent("\n".join(t for _, t in block)), line)], [], python_code=True)
            elif lang in SHELL_LANGS and block and block[0][1].startswith("#!"):
                element = Element(rel, line, "block", [Command("\n".join(t for _, t in block), line)], [])
            elif lang in SHELL_LANGS or lang == "":
                commands = logical_lines(block, every_line=lang in SHELL_LANGS)
                if commands:
                    element = Element(rel, line, "block", commands, [])
        if element is None:
            if pending is not None:
                raise DocError(f"{rel}:{pending_at}: docs-test marker before a block with no command")
            continue
        element.directives, pending = pending or [], None
        result.append(element)
    if pending is not None:
        raise DocError(f"{rel}:{pending_at}: docs-test marker applies to nothing")
    return result


def scene_elements(path: str) -> list[Element]:
    rel = os.path.relpath(path, ROOT)
    result: list[Element] = []
    comment: list[tuple[int, str]] = []
    for number, line in enumerate(open(path, encoding="utf-8").read().split("\n"), 1):
        if line.startswith("#"):
            comment.append((number, line[1:]))
    pending: list[Directive] | None = None
    pending_at = 0
    i = 0
    while i < len(comment):
        number, text = comment[i]
        i += 1
        stripped = text.strip()
        if stripped.startswith("docs-test:"):
            if pending is not None:
                raise DocError(f"{rel}:{pending_at}: docs-test marker applies to nothing")
            pending, pending_at = parse_marker(stripped[len("docs-test:"):], f"{rel}:{number}"), number
            continue
        if not is_command_start(stripped):
            continue
        indent = len(text) - len(text.lstrip())
        remark = re.compile(r"\s+\([^()]*\)\s*$")  # a closing remark: (CPU size), (a GPU job)
        parts = [remark.sub("", stripped)]
        depth = 1 if COMPOUND.match(stripped) else 0
        while i < len(comment):
            nxt = comment[i][1]
            nstripped = remark.sub("", nxt.strip())
            deeper = len(nxt) - len(nxt.lstrip()) > indent
            if not (parts[-1].endswith("\\") or depth > 0 or (deeper and nstripped.startswith("--"))):
                break
            if depth == 0 and not parts[-1].endswith("\\"):
                parts[-1] += " \\"  # options continued on the next line, as the shell needs it
            if COMPOUND.match(nstripped):
                depth += 1
            if re.match(r"^(done|fi)\b", nstripped):
                depth -= 1
            parts.append(nstripped)
            i += 1
        joined = "\n".join(parts)
        result.append(Element(rel, number, "scene comment", [Command(joined, number)], pending or []))
        pending = None
    if pending is not None:
        raise DocError(f"{rel}:{pending_at}: docs-test marker applies to nothing")
    return result


def all_elements(errors: list[str], root: str = ROOT) -> list[Element]:
    out: list[Element] = []
    docs = [os.path.join(root, "README.md")] + sorted(glob.glob(os.path.join(root, "docs", "*.md")))
    for path in docs + sorted(glob.glob(os.path.join(root, "scenes", "*.toml"))):
        try:
            out += markdown_elements(path) if path.endswith(".md") else scene_elements(path)
        except DocError as e:
            errors.append(str(e))
    return out


def all_plans(rules: dict, full: bool, present: set[str], errors: list[str]) -> list[Plan]:
    plans = []
    for e in all_elements(errors):
        try:
            plans.append(plan_element(e, rules, full, present))
        except DocError as err:
            errors.append(str(err))
    return plans


# ---------------------------------------------------------------- rules and planning

def load_rules() -> dict:
    with open(RULES, "rb") as f:
        return tomllib.load(f)


@dataclasses.dataclass
class Step:
    text: str              # the command to run (bash)
    shown: str             # as written
    line: int
    expect: int = 0
    creates: list[str] = dataclasses.field(default_factory=list)
    timeout: float = 0     # seconds; 0: the run's default (--timeout)
    before: list[str] = dataclasses.field(default_factory=list)
    dry: str = ""          # a ci rule's check of a dry run: the regex its output must match
    snippet: str = ""      # python code (run as a file)


@dataclasses.dataclass
class Plan:
    element: Element
    steps: list[Step]
    skipped: str = ""      # why nothing runs (skip:, full:, ci:)
    apart: bool = False    # each command in a sandbox of its own
    partly_skipped: list = dataclasses.field(default_factory=list)  # (Command, why) not run


def split_segments(text: str) -> list[tuple[int, int]]:
    """(start, end) of each simple command: split at ; && || | & and newlines outside quotes."""
    spans, start, i, quote = [], 0, 0, ""
    while i < len(text):
        c = text[i]
        if quote:
            if c == quote:
                quote = ""
            elif c == "\\" and quote == '"':
                i += 1
        elif c in "'\"":
            quote = c
        elif c == "\\":
            i += 1
        elif c == "#" and (i == 0 or text[i - 1].isspace()):
            end = text.find("\n", i)
            spans.append((start, i))
            i = len(text) if end < 0 else end
            start = i
            continue
        elif c in ";|&\n":
            spans.append((start, i))
            while i + 1 < len(text) and text[i + 1] in "|&":
                i += 1
            start = i + 1
        i += 1
    spans.append((start, len(text)))
    return [(a, b) for a, b in spans if text[a:b].strip()]


def arnoldweb_call(words: list[str]) -> tuple[str, str] | None:
    """(subcommand, scene or directory) when the simple command runs arnoldweb."""
    # after a launcher or wrapper: mpirun -n 4, /usr/bin/time -v, stop-at-checkpoint OUT
    k = next((k for k, w in enumerate(words) if w in {"arnoldweb", "build/arnoldweb"}), len(words))
    words = words[k:]
    if len(words) < 2 or words[0] not in {"arnoldweb", "build/arnoldweb"}:
        return None
    rest, k, target = words[2:], 0, ""
    while k < len(rest):
        if rest[k] in VALUE_OPTIONS:
            if rest[k] == "--scene":
                target = rest[k + 1] if k + 1 < len(rest) else ""
            k += 2
            continue
        if not rest[k].startswith("-") and not target:
            target = rest[k]
        k += 1
    return words[1], target


def map_devices(text: str, present: set[str]) -> str:
    def one(m: re.Match) -> str:
        return m.group(0) if m.group(0) in present else "cpu"
    text = re.sub(r"\b(?:cuda|opencl):\d+\b", one, text)

    def dedupe(m: re.Match) -> str:
        seen = []
        for x in m.group(0).split(","):
            if x not in seen:
                seen.append(x)
        return ",".join(seen)
    return re.sub(r"\b(?:cpu|cuda:\d+|opencl:\d+)(?:,(?:cpu|cuda:\d+|opencl:\d+))+\b", dedupe, text)


def adapt(text: str, element: Element, rules: dict, full: bool, present: set[str], rule: dict | None = None) -> str:
    """The command as it runs here: replacements, devices, sizes, extra arguments."""
    for d in element.directives:
        if d.verb == "replace" and d.applies(text) and not (d.ci_only and full):
            a, b = shlex.split(d.value)
            d.used = True
            text = text.replace(a, b)
    text = map_devices(text, present)
    # what a command writes to /tmp goes into the sandbox's tmp/
    text = re.sub(r"(?<![\w/.~$])/tmp/", "tmp/", text)
    if rule and rule.get("rewrite"):
        text = re.sub(rule["rewrite"][0], rule["rewrite"][1], text)
    scale = set(rules.get("scale_keys", []))
    inserts: list[tuple[int, str]] = []
    for n, (a, b) in enumerate(split_segments(text)):
        segment = text[a:b]
        try:
            call = arnoldweb_call(shlex.split(segment))
        except ValueError:
            call = None
        head, tail = [], []  # shell words, quoted: after the subcommand, and at the end
        option = "--scene-set" if call and call[0] == "bench" else "--set"
        if call and not full and (call[0] in {"run", "accuracy"} or (call[0] in {"bench", "serve"} and
                                                                     call[1].endswith(".toml"))):
            sizes = rules.get("sizes", {}).get(call[1])
            if sizes is None:
                raise DocError(f"{element.where}: tests/docs/rules.toml has no CI size for {call[1]!r} "
                               f"(add it to [sizes])")
            # the scene's CI size: its scale (trajectories, resolutions) wins over the command's,
            # the rest (durations, intervals) is the command's where it sets them
            for value in sizes:
                (tail if value.split("=")[0] in scale else head).extend([option, shlex.quote(value)])
        for d in element.directives:
            if not d.applies(segment) or (d.ci_only and full):
                continue
            if d.verb == "set" and call and call[0] in {"run", "check", "accuracy", "continue", "bench"}:
                d.used = True
                for value in shlex.split(d.value):
                    tail += [option, shlex.quote(value)]
            if d.verb == "args":
                d.used = True
                tail.append(d.value)
        if rule and rule.get("dry") and n == 0:
            tail.append(rule["dry"])
        if head:
            m = re.search(r"\b(?:arnoldweb|build/arnoldweb)\s+\S+", segment)
            inserts.append((a + m.end(), " " + " ".join(head)))
        if tail:
            end = b
            while end > a and text[end - 1].isspace():
                end -= 1
            if text[a:end].endswith("\\"):
                end -= 1
            inserts.append((end, " " + " ".join(tail)))
    for at, add in sorted(inserts, reverse=True):
        text = text[:at] + add + text[at:]
    return text


def plan_element(element: Element, rules: dict, full: bool, present: set[str]) -> Plan:
    for d in element.directives:
        if d.verb in {"skip", "full", "ci"} and not d.scope:
            d.used = True
            if d.verb == "ci":
                check_ci_claim(element, element.commands, d.value)
            if d.verb == "skip" or (d.verb == "full" and not full) or d.verb == "ci":
                return Plan(element, [], f"{d.verb}: {d.value}")
    steps = []
    skipped = []
    for command in element.commands:
        text = command.text
        skip = None
        for d in element.directives:  # the first that matches decides
            if d.verb in {"skip", "full", "ci"} and d.scope and d.applies(text) and skip is None:
                d.used = True
                if d.verb == "ci":
                    check_ci_claim(element, [command], d.value)
                if d.verb == "skip" or (d.verb == "full" and not full) or d.verb == "ci":
                    skip = f"{d.verb}: {d.value}"
                else:
                    break
        program = program_of(text) if not element.python_code else "python"
        bare = re.sub(r"^(\s*[A-Za-z_][A-Za-z0-9_]*=\S*\s+(\\\s+)?)+", "", text)
        rule = next((r for r in rules.get("programs", [])
                     if re.search(r["match"], bare) or re.search(r["match"], text)), None)
        if skip is None and rule and rule.get("skip"):
            skip = "skip: " + rule["skip"]
        if skip is None and rule and rule.get("ci"):
            check_ci_claim(element, [command], rule["ci"])
            skip = "ci: " + rule["ci"]
        if skip is None and not element.python_code and PLACEHOLDER.search(text.replace("...\n", "")) and \
                not any(d.verb == "replace" and d.applies(text) for d in element.directives) and \
                re.search(r"(<[^>]*>|(?<![\w.])\.\.\.(?![\w.])|…)", text):
            raise DocError(f"{element.where}: {text!r} has a placeholder: give it a marker (replace or skip)")
        if skip:
            skipped.append((command, skip))
            continue
        step = Step("", text, command.line)
        if element.python_code:
            step.snippet = text
            for d in element.directives:
                if d.verb == "replace" and not (d.ci_only and full):
                    a, b = shlex.split(d.value)
                    d.used = True
                    step.snippet = step.snippet.replace(a, b)
            step.text = "python docs_test_snippet.py"
        else:
            step.text = adapt(text, element, rules, full, present, rule)
        if rule and rule.get("dry"):
            step.dry = rule["expect"]
        for d in element.directives:
            if not d.applies(text) or (d.ci_only and full):
                continue
            if d.verb == "exit":
                d.used, step.expect = True, int(d.value)
            elif d.verb == "creates":
                d.used = True
                step.creates += d.value.split()
            elif d.verb == "timeout":
                d.used, step.timeout = True, float(d.value)
            elif d.verb == "before":
                d.used = True
                step.before.append(adapt(d.value, element, rules, full, present))
            elif d.verb in {"python", "apart"}:
                d.used = True
        if full:
            step.timeout = 24 * 3600
        steps.append(step)
    for d in element.directives:
        if d.verb == "set" and full:
            d.used = True
        if d.ci_only and full:
            d.used = True
        if not d.used:
            raise DocError(f"{element.where}: docs-test directive {d.verb} {d.value!r}"
                             + (f" [{d.scope}]" if d.scope else "") + " applies to no command")
    if not steps and skipped:
        return Plan(element, [], "; ".join(sorted({s for _, s in skipped})))
    return Plan(element, steps, apart=any(d.verb == "apart" for d in element.directives), partly_skipped=skipped)


def check_ci_claim(element: Element, commands: list[Command], claim: str) -> None:
    path = os.path.join(ROOT, claim.split()[0])
    if not os.path.isfile(path):
        raise DocError(f"{element.where}: docs-test ci: {claim.split()[0]} is no file")
    text = open(path, encoding="utf-8").read()
    for c in commands:
        if program_of(c.text) not in text:
            raise DocError(f"{element.where}: docs-test ci: {claim.split()[0]} does not run {program_of(c.text)}")


# ---------------------------------------------------------------- running

SANDBOX_COPIES = ["scenes", "bench", "scripts", "examples"]


def make_sandbox(build: str) -> str:
    box = tempfile.mkdtemp(prefix="arnoldweb-docs-")
    for d in SANDBOX_COPIES:
        if os.path.isdir(os.path.join(ROOT, d)):
            shutil.copytree(os.path.join(ROOT, d), os.path.join(box, d), symlinks=True)
    os.makedirs(os.path.join(box, "docs", "img"))
    os.makedirs(os.path.join(box, "tmp"))
    for f in glob.glob(os.path.join(ROOT, "docs", "*.md")) + [os.path.join(ROOT, "README.md")]:
        shutil.copy(f, os.path.join(box, os.path.relpath(f, ROOT)))
    if os.path.isdir(os.path.join(ROOT, "docs", "data")):
        shutil.copytree(os.path.join(ROOT, "docs", "data"), os.path.join(box, "docs", "data"))
    os.symlink(build, os.path.join(box, "build"))
    os.symlink(os.path.join(ROOT, "tests"), os.path.join(box, "tests"))  # (this test, for the docs' own commands)
    # the wheel the python suite installed (scripts/test-python.sh), where the docs install it from
    wheel = os.environ.get("ARNOLDWEB_WHEEL")
    if wheel and os.path.isfile(wheel):
        os.makedirs(os.path.join(box, "dist"))
        for at in (box, os.path.join(box, "dist")):
            os.symlink(wheel, os.path.join(at, os.path.basename(wheel)))
    return box


def summaries_since(box: str, since: float) -> list[str]:
    found = []
    for dirpath, dirnames, filenames in os.walk(box):
        dirnames[:] = [d for d in dirnames if os.path.join(dirpath, d) != os.path.join(box, "build")]
        if "summary.json" in filenames and os.path.getmtime(os.path.join(dirpath, "summary.json")) >= since:
            found.append(os.path.join(dirpath, "summary.json"))
    return found


def shell(command: str, box: str, env: dict, timeout: float) -> tuple[int, str, dict]:
    """Runs `command` with bash in the sandbox as one line of a shell session: its exit status,
    its output, and the environment it leaves (`. .venv/bin/activate` holds for the next line).
    On a timeout its whole process group is killed."""
    saved = os.path.join(box, ".docs-test-env")
    script = command + '\n__docs_test_rc=$?; env -0 > "$DOCS_TEST_ENV"; exit $__docs_test_rc\n'
    p = subprocess.Popen(["bash", "-c", script], cwd=box, env=dict(env, DOCS_TEST_ENV=saved),
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, start_new_session=True)
    try:
        out, _ = p.communicate(timeout=timeout)
        rc = p.returncode
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        out, _ = p.communicate()
        out += f"\ntimed out after {timeout:.0f} s\n".encode()
        rc = -1
    after = env
    if os.path.isfile(saved):
        pairs = open(saved, "rb").read().decode(errors="replace").split("\0")
        after = dict(x.split("=", 1) for x in pairs if "=" in x)
        after.pop("DOCS_TEST_ENV", None)
        os.remove(saved)
    return rc, out.decode(errors="replace"), after


def run_step(step: Step, box: str, env: dict, timeout: float) -> tuple[list[str], str, dict]:
    """Runs one command (and its setup) in the sandbox: the problems found, its log and the
    environment it leaves."""
    timeout = step.timeout or timeout
    log = []
    for before in step.before:
        rc, out, env = shell(before, box, env, timeout)
        log.append(f"$ {before}   [setup]\n{out[-6000:]}exit {rc}")
        if rc != 0:
            return [f"its setup failed (exit {rc})"], "\n".join(log), env
    if step.snippet:
        with open(os.path.join(box, "docs_test_snippet.py"), "w") as f:
            f.write(step.snippet)
    started = time.time() - 1
    rc, out, env = shell(step.text, box, env, timeout)
    problems = []
    if rc != step.expect:
        problems.append(f"exit {rc}, expected {step.expect}")
    if step.dry and not re.search(step.dry, out, re.M):
        problems.append(f"its output does not match {step.dry!r}")
    runs = []
    for a, b in split_segments(step.text):
        try:
            call = arnoldweb_call(shlex.split(step.text[a:b]))
        except ValueError:
            call = None
        if call and call[0] in {"run", "continue", "resume"} and "stop-at-checkpoint" not in step.text[a:b]:
            runs.append(call[0])  # (a run stopped on purpose leaves a checkpoint instead)
    if rc == 0 and runs and not summaries_since(box, started):
        problems.append(f"`arnoldweb {runs[0]}` wrote no summary.json")
    for path in step.creates:
        if not glob.glob(os.path.join(box, path)):
            problems.append(f"{path} does not exist")
    shown = step.text if step.text == step.shown else f"{step.text}\n  (as written: {step.shown})"
    log.append(f"$ {shown}\n{out[-6000:]}exit {rc}" + "".join(f"\nFAILED: {p}" for p in problems))
    return problems, "\n".join(log), env


def run_plan(plan: Plan, env: dict, build: str, keep: bool = False, timeout: float = 300) -> tuple[bool, str, float]:
    """Runs an element's commands in order, in one sandbox (one each with `apart`)."""
    t0 = time.monotonic()
    boxes, logs, ok = [], [], True
    try:
        for k, step in enumerate(plan.steps):
            if not boxes or plan.apart:
                boxes.append(make_sandbox(build))
                session = env
            problems, log, session = run_step(step, boxes[-1], session, timeout)
            logs.append(log)
            if problems:
                ok = False
                break
    finally:
        for box in boxes:
            if keep:
                logs.append(f"(sandbox kept: {box})")
            else:
                shutil.rmtree(box, ignore_errors=True)
    return ok, "\n".join(logs), time.monotonic() - t0


def devices_present(cli: str) -> set[str]:
    try:
        out = subprocess.run([cli, "devices"], capture_output=True, text=True, timeout=120).stdout
    except (OSError, subprocess.TimeoutExpired):
        return {"cpu"}
    return {line.split()[0] for line in out.splitlines() if re.match(r"^(cpu|cuda:\d+|opencl:\d+)\s", line)}


def environment(cli: str, python: str | None) -> tuple[dict, str]:
    bindir = tempfile.mkdtemp(prefix="arnoldweb-docs-bin-")
    os.symlink(os.path.abspath(cli), os.path.join(bindir, "arnoldweb"))
    env = dict(os.environ)
    path = bindir
    if python:  # its environment's python, python3 and pip (a venv's, not resolved), after this arnoldweb
        path += os.pathsep + os.path.dirname(python)
    # the test's helpers (stop-at-checkpoint) for the markers' setup commands
    path += os.pathsep + os.path.dirname(os.path.abspath(__file__))
    env["PATH"] = path + os.pathsep + env.get("PATH", "")
    env["ARNOLDWEB_DEVICE"] = env.get("ARNOLDWEB_DOCS_DEVICE", "cpu")
    env["MPLBACKEND"] = "Agg"
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    env.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")
    return env, bindir


def select(plans: list[Plan], pattern: str | None) -> list[Plan]:
    if not pattern:
        return plans
    return [p for p in plans if pattern in p.element.where or any(pattern in c.text for c in p.element.commands)]


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--cli", help="the arnoldweb command to run (build/arnoldweb)")
    ap.add_argument("--build", help="the build directory (default: the CLI's)")
    ap.add_argument("--python", help="run the python commands too, with this python (the python suite's)")
    ap.add_argument("--only-python", action="store_true", help="run the python commands only")
    ap.add_argument("--full", action="store_true", help="the commands as written: no CI sizes (hours; GPU jobs)")
    ap.add_argument("--list", action="store_true", help="print every command and how it runs, run nothing")
    ap.add_argument("-k", dest="pattern", help="only the elements whose source or text contains this")
    ap.add_argument("-j", "--jobs", type=int, default=os.cpu_count() or 2)
    ap.add_argument("--keep", action="store_true", help="keep the sandboxes")
    ap.add_argument("--timeout", type=float, default=300, help="seconds a command may take at CI size")
    args = ap.parse_args(argv)

    rules = load_rules()
    present = devices_present(args.cli) if args.cli else {"cpu"}
    errors: list[str] = []
    plans = select(all_plans(rules, args.full, present, errors), args.pattern)
    runnable = [p for p in plans if p.steps and (p.element.is_python == bool(args.only_python) or
                                                (args.python and not args.only_python))]
    python_elsewhere = [p for p in plans if p.steps and p.element.is_python and not args.python]
    if args.list:
        for p in plans:
            tag = "skipped (" + p.skipped + ")" if p.skipped else ("python suite" if p.element.is_python else "runs")
            print(f"{p.element.where} [{p.element.what}] {tag}")
            for s in p.steps:
                print("    " + (s.snippet.replace("\n", "\n    ") if s.snippet else s.text))
            for c, why in p.partly_skipped:
                print(f"    (not run: {c.text.splitlines()[0]}: {why})")
        for e in errors:
            print(f"ERROR: {e}")
        return 1 if errors else 0
    if not args.cli:
        ap.error("--cli is required to run commands")
    env, bindir = environment(args.cli, args.python)
    build = os.path.abspath(args.build or os.path.dirname(os.path.abspath(args.cli)))
    t0 = time.monotonic()
    failed = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        futures = {pool.submit(run_plan, p, env, build, args.keep, args.timeout): p for p in runnable}
        for f in concurrent.futures.as_completed(futures):
            p = futures[f]
            ok, log, seconds = f.result()
            print(f"{'ok  ' if ok else 'FAIL'} {seconds:6.1f} s  {p.element.where} ({len(p.steps)} command"
                  f"{'s' if len(p.steps) != 1 else ''})", flush=True)
            if not ok:
                failed.append(p)
                print("    " + log.replace("\n", "\n    "), flush=True)
    shutil.rmtree(bindir, ignore_errors=True)
    skipped = [p for p in plans if p.skipped]
    partly = [(p, c, why) for p in plans for c, why in p.partly_skipped]
    print(f"\ndocs-commands: {len(runnable)} elements run ({sum(len(p.steps) for p in runnable)} commands) in "
          f"{time.monotonic() - t0:.0f} s, {len(failed)} failed; "
          f"{len(python_elsewhere)} left to the python suite; {len(skipped) + len(partly)} not run, as marked:")
    for p in skipped:
        print(f"  {p.element.where}: {p.skipped}")
    for p, c, why in partly:
        print(f"  {p.element.where}: {c.text.splitlines()[0][:70]}: {why}")
    for p in failed:
        print(f"FAILED: {p.element.where}")
    for e in errors:
        print(f"ERROR: {e}")
    return 1 if failed or errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
