"""The README's Python examples run as written.

    python3 test_readme_examples.py README.md SOURCE_DIR BUILD_DIR PVPYTHON WORKDIR

Each ```python block of the README is run from SOURCE_DIR (the examples use
paths relative to the repository root) with `build/` replaced by BUILD_DIR:
blocks that import paraview.simple with pvpython, the others with this
interpreter. A block passes if it exits 0 and prints a positive count last.
"""
import os
import re
import subprocess
import sys


def main():
    readme, source, build, pvpython, work = sys.argv[1:6]
    os.makedirs(work, exist_ok=True)
    blocks = re.findall(r"```python\n(.*?)```", open(readme).read(), re.S)
    assert len(blocks) >= 2, "expected the plain-VTK and the paraview.simple examples"
    for i, code in enumerate(blocks):
        code = code.replace('"build/', '"%s/' % build.rstrip("/"))
        code = code.replace('SaveData("recon.vtu"', 'SaveData("%s/recon.vtu"' % work)
        path = os.path.join(work, "example%d.py" % i)
        with open(path, "w") as f:
            f.write(code)
        interpreter = pvpython if "paraview.simple" in code else sys.executable
        run = subprocess.run([interpreter, path], cwd=source, capture_output=True, text=True,
                             timeout=300)
        lines = [l for l in run.stdout.splitlines() if l.strip()]
        last = lines[-1].split()[-1] if lines else ""
        print("example %d (%s): exit %d, last output %r" % (i, os.path.basename(interpreter),
                                                            run.returncode, lines[-1:]))
        assert run.returncode == 0, run.stderr[-2000:]
        assert last.isdigit() and int(last) > 0, "no positive count printed: %r" % lines[-1:]
    print("PASS")


main()
