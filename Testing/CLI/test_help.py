"""Every command's help fits a terminal of 80 columns and documents every option.

The option help is written as sentences and wrapped by the help formatter
(Apps/CommandLine.cxx); a formatter that stops wrapping, or an option added
without a description, shows here.

usage: test_help.py FLOWRECON WORKDIR
"""

import re
import subprocess
import sys

FLOWRECON = sys.argv[1]
COMMANDS = ["complex", "info", "reconstruct", "diagram"]

failures = []
for words in [[]] + [[c] for c in COMMANDS]:
    run = subprocess.run([FLOWRECON, *words, "--help"], capture_output=True, text=True)
    name = " ".join(words) or "flowrecon"
    if run.returncode != 0 or run.stderr:
        failures.append(f"{name} --help: exit {run.returncode}, stderr {run.stderr!r}")
        continue
    lines = run.stdout.splitlines()
    failures += [f"{name} --help: {len(line)} columns: {line!r}" for line in lines if len(line) > 80]
    if not words:
        continue
    # An option line: two spaces, the names, then its description on the same
    # line or, for a long name, on the next one.
    options = [i for i, line in enumerate(lines) if re.match(r"^  (-\w, )?(    )?--?\w", line)]
    if len(options) < 3:
        failures.append(f"{name} --help lists {len(options)} options")
    for i in options:
        text = re.sub(r"^  (-\w, )?(    )?--?[\w-]+( [A-Z][\w.|]*)?", "", lines[i]).strip()
        following = lines[i + 1] if i + 1 < len(lines) else ""
        if not text and not following.startswith(" " * 26):
            failures.append(f"{name} --help: no description for {lines[i].strip()!r}")
    print(f"{name}: {len(lines)} lines, {len(options)} options")

for failure in failures:
    print("FAIL:", failure)
sys.exit(1 if failures else 0)
