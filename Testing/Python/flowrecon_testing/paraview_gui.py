"""Start the ParaView Qt GUI from a test (/usr/bin/python3) in a fresh settings
folder and collect what it prints: the tests then read its output, never the
user's settings."""
import os
import subprocess
import sys


def say(message):
    sys.stdout.write(message + "\n")
    sys.stdout.flush()


def fresh_home(outdir, settings=None):
    """The environment of a GUI with its own settings under OUTDIR/home: no welcome
    dialog, and the user settings `settings` (JSON text) or none."""
    config = os.path.join(outdir, "home", ".config", "ParaView")
    os.makedirs(config, exist_ok=True)
    with open(os.path.join(config, "ParaView5.11.0.ini"), "w") as f:
        f.write("[General]\nGeneralSettings.ShowWelcomeDialog=0\n")
    user_settings = os.path.join(config, "ParaView-UserSettings.json")
    if os.path.exists(user_settings):
        os.remove(user_settings)
    if settings is not None:
        with open(user_settings, "w") as f:
            f.write(settings)
    return dict(os.environ, HOME=os.path.join(outdir, "home"),
                XDG_CONFIG_HOME=os.path.join(outdir, "home", ".config"))


def run_gui(cmd, env, cwd, timeout):
    """(exit code, stdout and stderr) of the GUI; 124 when it timed out."""
    say("running: %s (in %s)" % (" ".join(cmd), cwd or os.getcwd()))
    try:
        result = subprocess.run(cmd, env=env, cwd=cwd, stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, timeout=timeout)
    except subprocess.TimeoutExpired as e:
        return 124, (e.output or b"").decode(errors="replace") + "\n(timed out)"
    return result.returncode, result.stdout.decode(errors="replace")


def run_paraview(paraview, plugin_dir, outdir, events, args=(), settings=None, cwd=None,
                 timeout=240):
    """Run the GUI with the QtTesting events (a list of XML lines) in a fresh settings
    folder; return (exit code, output)."""
    env = fresh_home(outdir, settings)
    xml = os.path.join(outdir, "events.xml")
    with open(xml, "w") as f:
        f.write('<?xml version="1.0" ?>\n<pqevents>\n%s\n</pqevents>\n' % "\n".join(events))
    env["PV_PLUGIN_PATH"] = plugin_dir
    cmd = [paraview] + list(args) + ["--test-script=" + xml, "--exit"]
    return run_gui(cmd, env, cwd, timeout)


def gui_errors(output):
    """Lines of the GUI's output that report a failure (test checks, VTK errors)."""
    return [line for line in output.splitlines()
            if "critical:" in line or "ERR|" in line or "FATL|" in line]
