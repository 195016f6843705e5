# docs.py - every example of README.md and the man pages held against
# the program: a command shown with its output gives that output (lines
# in order; "..." stands for lines left out); a phyllo-export command
# shown alone runs (exit 0) in a scratch folder beside the scenes; an
# excerpt of a scene file ("# scenes/X.cfg (abridged)", or a literal
# block after ".Pa scenes/X.cfg") has each of its lines in that file.
# Usage: python3 docs.py PROGRAM SCRATCH
# Prints "ok - ..." and "not ok - ..." lines, as the suite's scripts.
import os
import re
import shlex
import subprocess
import sys

program, scratch = sys.argv[1], sys.argv[2]
here = os.getcwd()
os.makedirs(scratch, exist_ok=True)
if not os.path.exists(os.path.join(scratch, "scenes")):
    os.symlink(os.path.join(here, "scenes"), os.path.join(scratch, "scenes"))


def report(ok, what, why=""):
    print("%s - %s%s" % ("ok" if ok else "not ok", what,
                         "" if ok else ": " + why))


def roff(line):
    """A line of a literal block as the reader sees it."""
    for a, b in (("\\(dq", '"'), ("\\e", "\\"), ("\\-", "-"), ("\\&", ""),
                 ("\\(em", "--")):
        line = line.replace(a, b)
    return line


def blocks_readme():
    """README's examples: (name, lines) of each indented or fenced
    block, as a reader sees them."""
    text = open("README.md").read().split("\n")
    out, i = [], 0
    while i < len(text):
        if text[i].startswith("```"):
            j = i + 1
            while j < len(text) and not text[j].startswith("```"):
                j += 1
            out.append(("README.md:%d" % (i + 1), text[i + 1:j]))
            i = j + 1
        elif text[i].startswith("    ") and (i == 0 or not text[i - 1].strip()):
            j = i
            while j < len(text) and (text[j].startswith("    ") or
                                     not text[j].strip() and j + 1 < len(text)
                                     and text[j + 1].startswith("    ")):
                j += 1
            out.append(("README.md:%d" % (i + 1), [l[4:] for l in text[i:j]]))
            i = j
        else:
            i += 1
    return out


def blocks_man(page):
    """A man page's literal blocks, with the file a .Pa just before
    names (its excerpt)."""
    text = open(page).read().split("\n")
    out, named = [], None
    for i, line in enumerate(text):
        m = re.match(r"\.(?:Pq )?Pa (scenes/\S+\.cfg)", line)
        if m:
            named = m.group(1)
        if line.startswith(".Bd -literal"):
            j = i + 1
            while not text[j].startswith(".Ed"):
                j += 1
            out.append(("%s:%d" % (page, i + 1),
                        [roff(l) for l in text[i + 1:j]], named))
            named = None
        elif line.startswith(".Sh") or line.startswith(".Ss"):
            named = None
    return out


def norm(line):
    """A scene line without its comment and its spacing."""
    line = re.sub(r"#.*", "", line)
    return " ".join(line.split())


def excerpt(where, lines, path):
    want = [norm(l) for l in lines]
    want = [w for w in want if w and w != "..."]
    have = {norm(l) for l in open(path).read().split("\n")}
    missing = [w for w in want if w not in have]
    report(not missing, "%s: the excerpt of %s is its own lines" % (where,
           path), "not in the file: %s" % missing[:2])


def commands(where, lines):
    """'$ command' lines, '> ' continuations joined, each with the lines
    shown after it, up to the next command."""
    out, cur = [], None
    for line in lines:
        if line.startswith("$ "):
            cur = [line[2:], []]
            out.append(cur)
        elif line.startswith("> ") and cur is not None and not cur[1]:
            cur[0] += "\n" + line[2:]
        elif cur is not None:
            if cur[0].endswith("\\") and not cur[1]:
                cur[0] = cur[0][:-1] + " " + line.strip()
            else:
                cur[1].append(line)
    return out


def run(where, command, shown):
    first = command.split()[0]
    if first not in ("phyllo-export", "for", "printf"):
        return      # povray, blender: their own tests render and build
    if " -o " in command:
        shown = []  # what follows a command writing a file is no output
    shell = command.replace("phyllo-export", shlex.quote(program))
    root = here if shown else scratch
    res = subprocess.run(["sh", "-c", shell], cwd=root, capture_output=True,
                         text=True, timeout=300)
    shown = [l for l in shown if l.strip()]
    if not shown:
        report(res.returncode == 0, "%s: %s runs" % (where, command.split(
            "\n")[0][:60]), "exit %d: %s" % (res.returncode,
                                             res.stderr.strip()[:200]))
        return
    got = res.stdout.rstrip("\n").split("\n")
    # The lines shown, in order; "..." is lines left out.
    k, ok, gap = 0, True, False
    for want in shown:
        if want.strip() == "...":
            gap = True
            continue
        while k < len(got) and got[k] != want and gap:
            k += 1
        if k >= len(got) or got[k] != want:
            ok = False
            break
        k += 1
        gap = False
    report(ok and res.returncode == 0, "%s: %s gives what is shown" % (
        where, command[:60]), "the program wrote %r, shown %r" % (
        got[k] if k < len(got) else "(nothing)", want))


for where, lines in blocks_readme():
    head = lines[0] if lines else ""
    m = re.match(r"# (scenes/\S+\.cfg) \(abridged\)", head)
    if m:
        excerpt(where, lines[1:], m.group(1))
        continue
    for command, shown in commands(where, lines):
        run(where, command, shown)
for page in ("man/phyllo-export.1", "man/phyllo-export.5"):
    for where, lines, named in blocks_man(page):
        if named is not None and not any(l.startswith("$ ")
                                         for l in lines):
            excerpt(where, lines, named)
            continue
        for command, shown in commands(where, lines):
            run(where, command, shown)
