"""What the Abort button of ParaView's status bar does to a long Flow Complex run in
the ParaView Qt GUI (built-in session), measured in the real GUI (issue #10):

    FLOWRECON_PLUGIN=<build>/lib/paraview-5.11/plugins/FlowRecon/FlowRecon.so \\
    xvfb-run -a -s "-screen 0 1280x1024x24" paraview --dr --script=test_abort_gui.py

The GUI's Python has no Qt bindings in Debian's ParaView 5.11, so the Qt objects are
reached through ctypes and the exported C++ symbols of Qt 5 and ParaView's pqCore:
pqCoreUtilities::MainWidget, qt_qFindChild_helper, QAbstractButton::click,
pqProgressManager::triggerAbort, QObject::receivers, QCoreApplication::processEvents;
a real X click on the button goes through XTest.

Run 1 ("gui abort"): Flow Complex on FLOWRECON_ABORT_POINTS random points (default
50000) is applied with the Properties panel's Apply button if it is enabled, else (as
for proxies made from Python in ParaView 5.11) with Show(). From the filter's progress
observer (the only code that runs while the filter executes), 1 s into the run, the
script does everything a user or ParaView could do: a real X click on the status bar's
Abort button (XTest), QAbstractButton::click() on it, pqProgressManager::triggerAbort(),
and QCoreApplication::processEvents() so that the click is delivered. It records
whether the button was enabled, how many receivers pqProgressManager::abort() has, and
whether the algorithm's AbortExecute flag was set.
  * ParaView 5.11 (pinned): the button is disabled, abort() has no receiver, the flag
    stays 0, the run completes with the full output.
  * A ParaView that delivers the abort (ParaView >= 6.1 sets AbortExecute on the
    algorithm): the run must end within ABORT_LATENCY s of the click with an empty
    output, and the GUI must go on working.
Run 2 ("observer abort"): the same run, with vtkAlgorithm::SetAbortExecute(1) called
from the progress observer 1 s in (what ParaView >= 6.1 does): the run ends within
ABORT_LATENCY s, the output is empty, the filter warns "... aborted", and the GUI goes
on: since VTK 9.2.20230111 does not clear AbortExecute when a run starts, a changed
property re-runs to an empty output until SetAbortExecute(0); then the full output.
Between the runs, a control: with the button enabled by
pqProgressManager::setEnableAbort(true) (what ParaView >= 6.1 does during Apply), an
XTest click at the same place does emit
pqProgressManager::abort() -- so the click itself reaches the button.

Prints "test_abort_gui: PASS"/"FAIL" with os.write (print() goes to the Output
Messages window) and os._exit()s (the GUI has no quit from Python).
"""

import ctypes
import os
import time
import traceback

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403

ABORT_AFTER = 1.0     # s into the run when the abort is requested
ABORT_LATENCY = 3.0   # s from the request to the end of the run (the longest step
                      # between two abort polls of the flow complex on 5e4 points is
                      # about 2 s on this 2-core machine)


def say(message):
    os.write(1, (message + "\n").encode())


def check(condition, message):
    if not condition:
        raise AssertionError(message)


class Qt:
    """The few Qt / pqCore calls needed, through ctypes."""

    def __init__(self):
        c = ctypes
        self.core = c.CDLL("libQt5Core.so.5")
        self.widgets = c.CDLL("libQt5Widgets.so.5")
        self.pq = c.CDLL("libpqCore-pv5.11.so.1")
        self._from_utf8 = self.core._ZN7QString15fromUtf8_helperEPKci
        self._from_utf8.argtypes = [c.c_void_p, c.c_char_p, c.c_int]
        self._from_utf8.restype = c.c_void_p
        self._find_child = self.core[
            "_Z20qt_qFindChild_helperPK7QObjectRK7QStringRK11QMetaObject"
            "6QFlagsIN2Qt15FindChildOptionEE"]
        self._find_child.argtypes = [c.c_void_p, c.c_void_p, c.c_void_p, c.c_int]
        self._find_child.restype = c.c_void_p
        self._receivers = self.core._ZNK7QObject9receiversEPKc
        self._receivers.argtypes = [c.c_void_p, c.c_char_p]
        self._receivers.restype = c.c_int
        self._process = self.core[
            "_ZN16QCoreApplication13processEventsE6QFlagsIN10QEventLoop17ProcessEventsFlagEE"]
        self._process.argtypes = [c.c_int]
        self._process.restype = None
        self._enabled = self.widgets._ZNK7QWidget11isEnabledToEPKS_
        self._enabled.argtypes = [c.c_void_p, c.c_void_p]
        self._enabled.restype = c.c_bool
        self._click = self.widgets._ZN15QAbstractButton5clickEv
        self._click.argtypes = [c.c_void_p]
        self._click.restype = None
        self._to_global = self.widgets._ZNK7QWidget11mapToGlobalERK6QPoint
        self._to_global.argtypes = [c.c_void_p, c.c_void_p]
        self._to_global.restype = c.c_uint64
        self._app_core = self.pq._ZN17pqApplicationCore8instanceEv
        self._app_core.restype = c.c_void_p
        self._trigger = self.pq._ZN17pqProgressManager12triggerAbortEv
        self._trigger.argtypes = [c.c_void_p]
        self._trigger.restype = None
        self._set_enable_abort = self.pq._ZN17pqProgressManager14setEnableAbortEb
        self._set_enable_abort.argtypes = [c.c_void_p, c.c_bool]
        self._set_enable_abort.restype = None
        self._connect = self.core._ZN7QObject7connectEPKS_PKcS1_S3_N2Qt14ConnectionTypeE
        self._connect.argtypes = [c.c_void_p, c.c_void_p, c.c_char_p, c.c_void_p, c.c_char_p,
                                  c.c_int]
        self._connect.restype = c.c_void_p
        self._visible_to = self.widgets._ZNK7QWidget11isVisibleToEPKS_
        self._visible_to.argtypes = [c.c_void_p, c.c_void_p]
        self._visible_to.restype = c.c_bool
        self._set_visible = self.widgets._ZN7QWidget10setVisibleEb
        self._set_visible.argtypes = [c.c_void_p, c.c_bool]
        self._set_visible.restype = None
        self._strings = []  # QStrings and connections are leaked on purpose (a few bytes)

    def meta(self, lib, cls):
        sym = "_ZN%d%s16staticMetaObjectE" % (len(cls), cls)
        return ctypes.addressof(ctypes.c_char.in_dll(lib, sym))

    def qstring(self, text):
        buf = (ctypes.c_void_p * 1)()
        data = text.encode()
        self._from_utf8(ctypes.addressof(buf), data, len(data))
        self._strings.append(buf)
        return ctypes.addressof(buf)

    def main_widget(self):
        # static QPointer<QWidget> pqCoreUtilities::MainWidget: {d, value}
        where = ctypes.addressof(ctypes.c_char.in_dll(self.pq, "_ZN15pqCoreUtilities10MainWidgetE"))
        return ctypes.c_void_p.from_address(where + ctypes.sizeof(ctypes.c_void_p)).value

    def find(self, parent, name, lib, cls):
        return self._find_child(parent, self.qstring(name), self.meta(lib, cls), 1)

    def progress_manager(self):
        return self.find(self._app_core(), "", self.pq, "pqProgressManager")

    def receivers(self, obj, signal):
        return self._receivers(obj, ("2" + signal).encode())  # SIGNAL(x) is "2x"

    def enabled(self, widget):
        return self._enabled(widget, None)

    def click(self, button):
        self._click(button)

    def trigger_abort(self, manager):
        self._trigger(manager)

    def process_events(self):
        self._process(0)

    def set_enable_abort(self, manager, enable):
        self._set_enable_abort(manager, enable)

    def connect(self, sender, signal, receiver, slot):
        """QObject::connect(sender, SIGNAL(signal), receiver, SLOT(slot))."""
        buf = (ctypes.c_void_p * 1)()  # the returned QMetaObject::Connection
        self._strings.append(buf)
        self._connect(ctypes.addressof(buf), sender, ("2" + signal).encode(), receiver,
                      ("1" + slot).encode(), 0)
        return bool(buf[0])

    def visible_to(self, widget, ancestor):
        return self._visible_to(widget, ancestor)

    def set_visible(self, widget, visible):
        self._set_visible(widget, visible)

    def global_pos(self, widget, x, y):
        point = (ctypes.c_int * 2)(x, y)
        packed = self._to_global(widget, ctypes.addressof(point))
        gx, gy = packed & 0xFFFFFFFF, packed >> 32
        return ctypes.c_int32(gx).value, ctypes.c_int32(gy).value


def x_click(x, y):
    """A real mouse click at root position (x, y) through XTest; False if impossible."""
    try:
        x11 = ctypes.CDLL("libX11.so.6")
        xtst = ctypes.CDLL("libXtst.so.6")
    except OSError:
        return False
    x11.XOpenDisplay.restype = ctypes.c_void_p
    x11.XOpenDisplay.argtypes = [ctypes.c_char_p]
    dpy = x11.XOpenDisplay(None)
    if not dpy:
        return False
    for f in (xtst.XTestFakeMotionEvent, xtst.XTestFakeButtonEvent):
        f.restype = ctypes.c_int
    xtst.XTestFakeMotionEvent.argtypes = [ctypes.c_void_p, ctypes.c_int, ctypes.c_int,
                                          ctypes.c_int, ctypes.c_ulong]
    xtst.XTestFakeButtonEvent.argtypes = [ctypes.c_void_p, ctypes.c_uint, ctypes.c_int,
                                          ctypes.c_ulong]
    x11.XFlush.argtypes = x11.XCloseDisplay.argtypes = [ctypes.c_void_p]
    xtst.XTestFakeMotionEvent(dpy, -1, x, y, 0)
    xtst.XTestFakeButtonEvent(dpy, 1, 1, 0)
    xtst.XTestFakeButtonEvent(dpy, 1, 0, 0)
    x11.XFlush(dpy)
    x11.XCloseDisplay(dpy)
    return True


def n_cells(proxy):
    return proxy.GetDataInformation().GetNumberOfCells()


def apply(qt, accept):
    """Press the Properties panel's Apply button (the user's path); False if disabled."""
    if not accept or not qt.enabled(accept):
        return False
    qt.click(accept)
    return True


def run(qt, points, seed, mode, accept, button, manager, warnings):
    """One Flow Complex run; mode "gui" (abort button etc.) or "observer"."""
    fc = FlowComplex(registrationName="FlowComplex-%s" % mode, Input=points)
    fc.PerturbationSeed = seed
    algorithm = fc.GetClientSideObject()
    state = {"t0": None, "requested": None, "flag_seen": None, "polls": 0}

    def on_progress(obj, event):
        now = time.time()
        if state["t0"] is None:
            state["t0"] = now
        state["polls"] += 1
        if obj.GetAbortExecute() and state["flag_seen"] is None:
            state["flag_seen"] = now
        if state["requested"] is None and now - state["t0"] >= ABORT_AFTER:
            state["requested"] = now
            if mode == "observer":
                obj.SetAbortExecute(1)
                return
            state["button_enabled"] = qt.enabled(button)
            state["abort_receivers"] = qt.receivers(manager, "abort()")
            x, y = qt.global_pos(button, 6, 6)
            state["x_click"] = x_click(x, y)
            qt.process_events()        # deliver the X click
            qt.click(button)           # what a click on an enabled button does
            qt.trigger_abort(manager)  # what the button is connected to
            qt.process_events()
            state["flag_after"] = obj.GetAbortExecute()
            if state["flag_after"] and state["flag_seen"] is None:
                state["flag_seen"] = time.time()

    tag = algorithm.AddObserver("ProgressEvent", on_progress)
    warn_tag = algorithm.AddObserver("WarningEvent", lambda o, e: warnings.append(mode))
    SetActiveSource(fc)
    qt.process_events()  # let the Properties panel show the new filter
    start = time.time()
    via = "Apply button" if apply(qt, accept) else "Show()"
    if via == "Show()":
        Show(fc)
        Render()
    fc.UpdatePipeline()
    end = time.time()
    algorithm.RemoveObserver(tag)
    algorithm.RemoveObserver(warn_tag)
    state.update(fc=fc, via=via, total=end - start, end=end, cells=n_cells(fc))
    return state


def main():
    plugin = os.environ.get("FLOWRECON_PLUGIN", "")
    npoints = int(os.environ.get("FLOWRECON_ABORT_POINTS", "50000"))
    ns = globals()
    if "FlowComplex" not in ns:
        check(os.path.exists(plugin), "plugin %r does not exist" % plugin)
        LoadPlugin(plugin, remote=False, ns=ns)
    check("FlowComplex" in ns, "the plugin did not define FlowComplex")
    say("test_abort_gui: ParaView %s, %d random points" % (
        servermanager.vtkSMProxyManager.GetParaViewSourceVersion(), npoints))

    qt = Qt()
    main_widget = qt.main_widget()
    check(main_widget, "no pqCoreUtilities::MainWidget")
    button = qt.find(main_widget, "AbortButton", qt.widgets, "QToolButton")
    check(button, "the status bar has no AbortButton")
    accept = qt.find(main_widget, "Accept", qt.widgets, "QPushButton")
    manager = qt.progress_manager()
    check(manager, "no pqProgressManager")
    say("test_abort_gui: idle: Abort button enabled=%s, pqProgressManager::abort() has %d "
        "receiver(s), enableAbort(bool) %d" % (
            qt.enabled(button), qt.receivers(manager, "abort()"),
            qt.receivers(manager, "enableAbort(bool)")))

    points = PointSource(registrationName="Cloud", NumberOfPoints=npoints, Radius=1.0)
    Show(points)
    points.UpdatePipeline()
    warnings = []

    # Run 1: the Abort button and everything behind it
    r = run(qt, points, 0, "gui", accept, button, manager, warnings)
    delivered = bool(r["flag_seen"])
    say("test_abort_gui: gui abort via %s: run %.1f s, %d progress events; at %.1f s the "
        "Abort button was enabled=%s, abort() receivers=%d, XTest click sent=%s; "
        "AbortExecute after click+triggerAbort+processEvents=%s; output %d cells" % (
            r["via"], r["total"], r["polls"], r["requested"] - r["t0"] if r["requested"] else -1,
            r.get("button_enabled"), r.get("abort_receivers", -1), r.get("x_click"),
            r.get("flag_after"), r["cells"]))
    check(r["requested"] is not None,
          "the run was shorter than %g s: use more points" % ABORT_AFTER)
    if delivered:
        latency = r["end"] - r["requested"]
        say("test_abort_gui: ParaView delivered the abort: the run ended %.2f s after the "
            "click" % latency)
        check(latency < ABORT_LATENCY, "run went on %.2f s after the abort" % latency)
        check(r["cells"] == 0, "aborted run has %d cells" % r["cells"])
    else:
        # ParaView 5.11: the abort never reaches the filter; pin what it does.
        check(not r["button_enabled"], "Abort button enabled but the abort was not delivered")
        check(r["abort_receivers"] == 0,
              "pqProgressManager::abort() has receivers but the abort was not delivered")
        check(r["cells"] > 0, "a run that was not aborted has an empty output")
        say("test_abort_gui: ParaView did NOT deliver the abort (ParaView 5.11: Abort button "
            "disabled, pqProgressManager::abort() unconnected); the run completed")

    # Control: with the button enabled (what ParaView >= 6.1 does during Apply), the
    # same XTest click reaches pqProgressManager::triggerAbort() and abort() is emitted
    # (seen through a test connection abort() -> AbortButton.hide()). Done before run 2,
    # whose warning opens the Output Messages window, which may cover the button.
    qt.set_enable_abort(manager, True)
    check(qt.connect(manager, "abort()", button, "hide()"), "connect abort() failed")
    x, y = qt.global_pos(button, 6, 6)
    control = x_click(x, y)
    deadline = time.time() + 5
    while control and qt.visible_to(button, main_widget) and time.time() < deadline:
        qt.process_events()
        time.sleep(0.05)
    reached = not qt.visible_to(button, main_widget)
    say("test_abort_gui: control: enabled Abort button at (%d, %d), XTest click sent=%s, "
        "abort() emitted=%s" % (x, y, control, reached))
    qt.set_visible(button, True)
    qt.set_enable_abort(manager, False)
    if control:
        check(reached, "an XTest click on the enabled Abort button did not emit abort()")


    # Run 2: AbortExecute set from the progress observer (what ParaView >= 6.1 does)
    r2 = run(qt, points, 1, "observer", accept, button, manager, warnings)
    check(r2["requested"] is not None, "the run was shorter than %g s" % ABORT_AFTER)
    latency = r2["end"] - r2["requested"]
    say("test_abort_gui: observer abort via %s: SetAbortExecute(1) at %.1f s, the run "
        "ended %.2f s later, output %d cells, warnings %s" % (
            r2["via"], r2["requested"] - r2["t0"], latency, r2["cells"], warnings))
    check(latency < ABORT_LATENCY, "run went on %.2f s after SetAbortExecute" % latency)
    check(r2["cells"] == 0, "aborted run has %d cells" % r2["cells"])
    check("observer" in warnings, "no warning from the aborted filter")

    # the GUI goes on. VTK 9.2.20230111 (ParaView 5.11) does not clear AbortExecute
    # when a run starts: a changed property re-runs to an empty output until the flag
    # is cleared; then the full output is computed.
    fc2 = r2["fc"]
    algorithm = fc2.GetClientSideObject()
    fc2.Input = PointSource(registrationName="Small", NumberOfPoints=2000, Radius=1.0)
    fc2.UpdatePipeline()
    sticky = algorithm.GetAbortExecute() == 1 and n_cells(fc2) == 0
    say("test_abort_gui: re-applied with the flag still set: %d cells (flag %d)" % (
        n_cells(fc2), algorithm.GetAbortExecute()))
    if not sticky:
        check(n_cells(fc2) > 0, "re-applied after an abort: empty output, flag cleared")
    algorithm.SetAbortExecute(0)
    fc2.PerturbationSeed = 2
    fc2.UpdatePipeline()
    check(n_cells(fc2) > 0, "re-applied after SetAbortExecute(0): empty output")
    say("test_abort_gui: re-applied after SetAbortExecute(0): %d cells" % n_cells(fc2))
    say("test_abort_gui: PASS")


try:
    main()
    status = 0
except Exception:  # noqa: BLE001 - report anything, then leave the GUI
    say(traceback.format_exc())
    say("test_abort_gui: FAIL")
    status = 1
if os.environ.get("FLOWRECON_EXIT", "1") == "1":
    os._exit(status)
