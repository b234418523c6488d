"""Qt and pqCore calls for the tests that run inside the ParaView Qt GUI
(paraview --script=...). The GUI's Python has no Qt bindings in Debian's ParaView
5.11, so the Qt objects are reached through ctypes and the exported C++ symbols of
Qt 5 and ParaView's pqCore / pqApplicationComponents.
"""

import ctypes
import os
import traceback


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
        self.components = c.CDLL("libpqApplicationComponents-pv5.11.so.1")
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

    def create_filter(self, group, name):
        """pqFiltersMenuReaction::createFilter: what choosing the filter in the
        Filters menu does (input: the active source; the Apply button turns on)."""
        f = self.components["_ZN21pqFiltersMenuReaction12createFilterERK7QStringS2_"]
        f.argtypes = [ctypes.c_void_p, ctypes.c_void_p]
        f.restype = ctypes.c_void_p
        return f(self.qstring(group), self.qstring(name))


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


def run_in_gui(main, name):
    """Runs main() in the GUI's Python, prints "NAME: PASS"/"FAIL" (with the
    traceback) to the terminal and, unless FLOWRECON_EXIT=0, leaves the GUI with
    os._exit(), since the GUI has no quit from Python."""
    try:
        main()
        status = 0
    except Exception:  # noqa: BLE001 - report anything, then leave the GUI
        say(traceback.format_exc())
        say("%s: FAIL" % name)
        status = 1
    if os.environ.get("FLOWRECON_EXIT", "1") == "1":
        os._exit(status)
