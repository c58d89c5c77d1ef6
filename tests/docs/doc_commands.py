#!/usr/bin/env python3
"""Runs every command shown in README.md and docs/*.md and compares its output
with the output shown (the conventions: docs/README.md, "How the commands are
checked").

    doc_commands.py PROMYK [FILE.md ...]            check (exit 1 on a difference)
    doc_commands.py --update PROMYK [FILE.md ...]   rewrite the outputs shown

PROMYK is the built binary. Without files: README.md and docs/*.md of the
repository this script lives in. Python 3 standard library only.
"""
import difflib
import os
import re
import subprocess
import sys
import tempfile

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ELLIPSIS = "…"
MARKER = re.compile(r"^<!--\s*(output|not run|exit|file|run as|pending):\s*(.*?)\s*-->\s*$")
FENCE = re.compile(r"^```(\S*)\s*$")
PROGRAM = re.compile(r"^(promyk|build/release/promyk)(\s|$)")
NUMBER = re.compile(r"[-+−]?\d+(?:[.,]\d+)*(?:[eE][-+−]?\d+)?")
COMMAND_SECONDS = 120


class Block:
    """A fenced block: its language, its lines (without the fences), the
    index of its first line in the file, and the markers above it."""

    def __init__(self, lang, first, lines, markers, fence_line):
        self.lang, self.first, self.lines, self.markers = lang, first, lines, markers
        self.fence_line = fence_line  # 1-based line of the opening fence

    def marker(self, name):
        return self.markers.get(name)


def blocks_of(lines):
    """The fenced blocks of a Markdown file, with the markers just above each
    (separated from it by blank lines at most)."""
    found, markers, k = [], {}, 0
    while k < len(lines):
        line = lines[k]
        fence = FENCE.match(line)
        marker = MARKER.match(line)
        if marker:
            markers[marker.group(1)] = marker.group(2)
        elif fence:
            end = k + 1
            while end < len(lines) and lines[end].rstrip() != "```":
                end += 1
            found.append(Block(fence.group(1), k + 1, lines[k + 1:end], markers, k + 1))
            markers, k = {}, end
        elif line.strip():
            markers = {}
        k += 1
    return found


def console_commands(block):
    """[(command, shown output lines)] of a console block."""
    commands = []
    for line in block.lines:
        if line.startswith("$ "):
            commands.append((line[2:], []))
        elif not commands:
            raise ValueError("a console block must start with a command ('$ promyk ...')")
        else:
            commands[-1][1].append(line)
    return commands


def shape(line):
    """A line with every number, and every '-' or '—' standing for a number
    not printed, as '#', and runs of spaces as one."""
    return " ".join("#" if word in ("-", "—") else word for word in NUMBER.sub("#", line).split())


def contains_in_order(shown, actual):
    """A recorded run against a smaller one: every line shown, by shape, in
    order among the lines printed, which may add lines of their own."""
    want = [shape(s) for s in shown if s.strip() != ELLIPSIS]
    got = iter(shape(a) for a in actual)
    return all(any(w == g for g in got) for w in want)


def segments(shown):
    """The shown lines cut at each '…' line."""
    parts = [[]]
    for line in shown:
        if line.strip() == ELLIPSIS:
            parts.append([])
        else:
            parts[-1].append(line)
    return parts


def matches(shown, actual, timing):
    norm = shape if timing else (lambda s: s.rstrip())
    shown_n, actual_n = [norm(s) for s in shown], [norm(s) for s in actual]
    parts = segments(shown_n)
    if len(parts) == 1:
        return shown_n == actual_n
    head, tail = parts[0], parts[-1]
    if actual_n[:len(head)] != head or len(head) + len(tail) > len(actual_n):
        return False
    if tail and actual_n[len(actual_n) - len(tail):] != tail:
        return False
    at, stop = len(head), len(actual_n) - len(tail)
    for part in parts[1:-1]:  # each middle part, in order, somewhere between
        while at + len(part) <= stop and actual_n[at:at + len(part)] != part:
            at += 1
        if at + len(part) > stop:
            return False
        at += len(part)
    return True


def updated(shown, actual):
    """The output to show: the whole output, or, where the shown one has '…'
    lines, as many lines before and after each as it shows now."""
    parts = segments(shown)
    if len(parts) == 1:
        return list(actual)
    head, tail = parts[0], parts[-1]
    if len(head) + len(tail) >= len(actual):
        return list(actual)
    result = actual[:len(head)]
    at, stop = len(head), len(actual) - len(tail)
    for part in parts[1:-1]:
        if not part:
            continue
        first = part[0].split()[:1]
        k = next((n for n in range(at, stop) if actual[n].rstrip() == part[0].rstrip()), None)
        if k is None:
            k = next((n for n in range(at, stop) if actual[n].split()[:1] == first), None)
        if k is None:
            continue  # the part is gone: leave it out
        result += [ELLIPSIS] + actual[k:min(k + len(part), stop)]
        at = min(k + len(part), stop)
    return result + [ELLIPSIS] + actual[stop:]


class Runner:
    def __init__(self, promyk, folder):
        self.folder = folder
        bin_dir = os.path.join(folder, ".bin")
        os.makedirs(bin_dir)
        os.makedirs(os.path.join(folder, "build", "release"))
        for link in (os.path.join(bin_dir, "promyk"), os.path.join(folder, "build", "release", "promyk")):
            os.symlink(os.path.abspath(promyk), link)
        for name in ("lessons", "tests", "docs"):
            os.symlink(os.path.join(REPO, name), os.path.join(folder, name))
        self.env = {k: v for k, v in os.environ.items() if k not in ("LC_ALL", "LC_MESSAGES", "LANGUAGE")}
        self.env["LANG"] = "C.UTF-8"
        self.env["PATH"] = bin_dir + os.pathsep + os.environ.get("PATH", "/usr/bin:/bin")

    def run(self, command):
        done = subprocess.run(["bash", "-c", command], cwd=self.folder, env=self.env, stdin=subprocess.DEVNULL,
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=COMMAND_SECONDS)
        text = done.stdout.decode("utf-8", errors="replace")
        lines = text.split("\n")
        if lines and lines[-1] == "":
            lines.pop()
        return done.returncode, lines


def check_file(path, promyk, update):
    """Runs the file's commands; returns (problems, commands run, new lines or None)."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    lines = text.split("\n")
    name = os.path.relpath(path, REPO)
    problems, count, replacements = [], 0, []
    with tempfile.TemporaryDirectory(prefix="promyk-docs-") as folder:
        runner = Runner(promyk, folder)
        for block in blocks_of(lines):
            where = f"{name}:{block.fence_line}"
            if block.marker("not run") is not None:
                if not block.marker("not run"):
                    problems.append(f"{where}: 'not run' needs a reason")
                continue
            if block.marker("file"):
                target = block.marker("file")
                content = "\n".join(block.lines) + "\n"
                with open(os.path.join(folder, target), "w", encoding="utf-8") as f:
                    f.write(content)
                twin = os.path.join(REPO, "docs", target)
                if os.path.isfile(twin) and open(twin, encoding="utf-8").read() != content:
                    problems.append(f"{where}: the block differs from docs/{target}, which the pictures use")
                continue
            if block.lang not in ("console", "sh"):
                continue
            timing = block.marker("output") == "timing" or block.marker("run as") is not None
            exit_code = int(block.marker("exit") or 0)
            if block.lang == "sh":
                commands = [(l, None) for l in block.lines if l.strip() and not l.lstrip().startswith("#")]
            else:
                try:
                    commands = console_commands(block)
                except ValueError as e:
                    problems.append(f"{where}: {e}")
                    continue
            new_block, changed = [], False
            for n, (command, shown) in enumerate(commands):
                if shown is not None:
                    new_block.append("$ " + command)
                if not PROGRAM.match(command):
                    problems.append(f"{where}: '{command}' is not a promyk command: mark the block "
                                    "<!-- not run: REASON --> if it must not run")
                    new_block += shown or []
                    continue
                to_run = block.marker("run as") or command
                count += 1
                try:
                    code, actual = runner.run(to_run)
                except subprocess.TimeoutExpired:
                    problems.append(f"{where}: '{to_run}' took over {COMMAND_SECONDS} s")
                    new_block += shown or []
                    continue
                expected_code = exit_code if n == len(commands) - 1 else 0
                wrong_exit = code != expected_code
                if wrong_exit:
                    problems.append(f"{where}: '{to_run}' exited with {code}, not {expected_code}:\n  "
                                    + "\n  ".join(actual[-10:]))
                if shown is None:
                    continue
                recorded = block.marker("run as") is not None
                if contains_in_order(shown, actual) if recorded else matches(shown, actual, timing):
                    new_block += shown
                elif update and not recorded and not wrong_exit:
                    new_block += updated(shown, actual)
                    changed = True
                else:
                    if update and recorded:
                        problems.append(f"{where}: a recorded run's shape differs from '{to_run}': "
                                        "record it again (see the text above the block)")
                    elif update:
                        pass  # the wrong exit code is reported: the output shown stays
                    else:
                        diff = difflib.unified_diff(shown, actual, "shown", "printed", lineterm="", n=2)
                        problems.append(f"{where}: the output of '{to_run}' differs from the one shown"
                                        + (" (compared by shape)" if timing else "") + ":\n  "
                                        + "\n  ".join(list(diff)[:60]))
                    new_block += shown
            if changed:
                replacements.append((block.first, block.first + len(block.lines), new_block))
    if not replacements:
        return problems, count, None
    for first, end, new in reversed(replacements):
        lines[first:end] = new
    return problems, count, lines


def main(argv):
    update = "--update" in argv
    args = [a for a in argv if a != "--update"]
    if not args or args[0].startswith("-"):
        print(__doc__.strip(), file=sys.stderr)
        return 2
    promyk = args[0]
    files = args[1:] or [os.path.join(REPO, "README.md")] + sorted(
        os.path.join(REPO, "docs", f) for f in os.listdir(os.path.join(REPO, "docs")) if f.endswith(".md"))
    all_problems, total = [], 0
    for path in files:
        problems, count, new_lines = check_file(path, promyk, update)
        all_problems += problems
        total += count
        if new_lines is not None:
            with open(path, "w", encoding="utf-8") as f:
                f.write("\n".join(new_lines))
            print(f"updated the outputs shown in {os.path.relpath(path, REPO)}")
    for problem in all_problems:
        print(problem, file=sys.stderr)
    print(f"{total} commands run from {len(files)} files, {len(all_problems)} problems")
    return 1 if all_problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
