"""Runs every code block of README.md and of docs/*.md that is tagged for
testing, as a user would run it from the repository:
    <!-- test: pvpython -->   a pvpython script
    <!-- test: python -->     Debian's python3 with the build's site-packages
    <!-- test: shell -->      sh, with the build's bin/ on PATH
    <!-- test: cpp FILE -->   the block appears verbatim in FILE (which another
                              test compiles and runs)
    <!-- test: file FILE -->  the block is FILE, whole
The README must hold a snippet per route (pvpython, Python, command line, C++);
the longer material in docs/, the C++ application's CMake recipe among it, is
tested the same way, and every kind must occur somewhere.
Usage: TestReadmeSnippets.py --source DIR --build DIR --temp DIR --pvpython EXE --python EXE
"""
import argparse
import glob
import os
import re
import shutil
import subprocess
import sys

parser = argparse.ArgumentParser()
parser.add_argument("--source", required=True)
parser.add_argument("--build", required=True)
parser.add_argument("--temp", required=True)
parser.add_argument("--pvpython", required=True)
parser.add_argument("--python", required=True)
args = parser.parse_args()

# The README first, then the docs/ pages in name order.
documents = ["README.md"] + sorted(os.path.relpath(path, args.source) for path in
                                   glob.glob(os.path.join(args.source, "docs", "*.md")))
snippets = []
malformed = []
for document in documents:
    with open(os.path.join(args.source, document)) as f:
        text = f.read()
    found = re.findall(r"<!-- test: (\w+)([^>]*?) -->\n```\w*\n(.*?)```", text, re.S)
    snippets += [(document, kind, target, code) for kind, target, code in found]
    # A tag (at the start of a line) not followed by a code block would leave
    # its block untested.
    tags = len(re.findall(r"^<!-- test:", text, re.M))
    if tags != len(found):
        malformed.append("%s: %d test tags, %d tagged code blocks" % (document, tags, len(found)))
work = os.path.join(args.temp, "readme")
shutil.rmtree(work, ignore_errors=True)
# The snippets use repository paths (Data/, Testing/, build/...): run them in
# a copy of that layout whose build/ is the build under test.
os.makedirs(work)
for directory in ("Data", "Testing"):
    os.symlink(os.path.join(args.source, directory), os.path.join(work, directory))
os.symlink(args.build, os.path.join(work, "build"))
env = dict(os.environ)
# What the snippets install into $HOME goes into the test's directory.
env["HOME"] = work
env["PYTHONPATH"] = os.path.join(args.build, "lib", "python3.11", "site-packages")
env["PATH"] = os.path.join(args.build, "bin") + os.pathsep + env["PATH"]

failures = list(malformed)
readme_kinds = set()
for number, (document, kind, target, code) in enumerate(snippets):
    if document == "README.md":
        readme_kinds.add(kind)
    label = "%s snippet %d (%s)" % (document, number + 1, kind)
    if kind in ("cpp", "file"):
        with open(os.path.join(args.source, target.strip())) as f:
            text = f.read()
        ok = code in text if kind == "cpp" else code == text
        relation = "in " if kind == "cpp" else "the whole of "
        print(("ok   " if ok else "FAIL ") + label + ": " + relation + target.strip())
        if not ok:
            failures.append(label + " is not " + relation + target.strip())
        continue
    script = os.path.join(work, "snippet%d" % (number + 1))
    with open(script, "w") as f:
        f.write(code)
    command = {"pvpython": [args.pvpython, script], "python": [args.python, script],
               "shell": ["sh", "-e", script]}.get(kind)
    if command is None:
        failures.append(label + ": unknown kind")
        continue
    result = subprocess.run(command, cwd=work, env=env, capture_output=True, text=True, timeout=300)
    output = (result.stdout + result.stderr).strip()
    print(("ok   " if result.returncode == 0 else "FAIL ") + label + ":\n    " + output.replace("\n", "\n    ")[-1500:])
    if result.returncode != 0:
        failures.append(label)

for kind in ("pvpython", "python", "shell", "cpp"):
    if kind not in readme_kinds:
        failures.append("no %s snippet found in README.md" % kind)
for kind in ("pvpython", "python", "shell", "cpp", "file"):
    if not any(s[1] == kind for s in snippets):
        failures.append("no %s snippet found in README.md or docs/" % kind)
if failures:
    print("\nFAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("\nAll %d snippets ran (%s)." % (len(snippets), ", ".join(
    "%s: %d" % (document, sum(1 for s in snippets if s[0] == document))
    for document in documents if any(s[0] == document for s in snippets))))
