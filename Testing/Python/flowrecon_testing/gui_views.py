"""What the tests read of the ParaView GUI's views and set on its pipeline items: the
point labels a render view draws and the changes they tell, and an item marked
modified as the Properties panel does."""
import ctypes

from flowrecon_testing.gui_qt import check


def label_texts(view):
    """The texts of the point labels the render view draws (its visible label
    mappers' input, in the built-in session)."""
    import vtkmodules.vtkRenderingLabel  # noqa: F401 (vtkLabeledDataMapper in Python)
    actors = view.GetClientSideObject().GetNonCompositedRenderer().GetActors2D()
    actors.InitTraversal()
    texts = []
    for _ in range(actors.GetNumberOfItems()):
        actor = actors.GetNextItem()
        mapper = actor.GetMapper()
        if actor.GetVisibility() and mapper is not None and mapper.IsA("vtkLabeledDataMapper"):
            data = mapper.GetInput()
            labels = data.GetPointData().GetAbstractArray("Label") if data else None
            if labels is not None:
                texts += [labels.GetValue(k) for k in range(labels.GetNumberOfValues())]
    return sorted(t for t in texts if t)


def label_changes(texts):
    """{(t_r as printed, Betti number): change} told by labels "t_r T: bk +-c, ...",
    a line per t_r."""
    told = {}
    for text in texts:
        for line in text.split("\n"):
            head, _, terms = line.partition(": ")
            for term in terms.split(", "):
                k, c = term.split(" ")
                key = (head, k)
                told[key] = told.get(key, 0) + int(c)
    return told


def expected_changes(data):
    """The same, summed over the points of an under-sampling output (`data`, a
    vtkPolyData with Threshold, Dimension and Change)."""
    pd = data.GetPointData()
    told = {}
    for k in range(data.GetNumberOfPoints()):
        key = ("t_r %.3g" % pd.GetArray("Threshold").GetValue(k),
               "b%d" % int(pd.GetArray("Dimension").GetValue(k)))
        told[key] = told.get(key, 0) + int(pd.GetArray("Change").GetValue(k))
    return told


def mark_modified(qt, proxy):
    """pqProxy::setModifiedState(MODIFIED) on the GUI's item of `proxy`, as editing a
    property in the Properties panel does: a change made from Python leaves Apply off."""
    model = qt.find(qt._app_core(), "", qt.pq, "pqServerManagerModel")
    find = qt.pq._ZN20pqServerManagerModel14findItemHelperEPKS_RK11QMetaObjectP10vtkSMProxy
    find.argtypes = [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p]
    find.restype = ctypes.c_void_p
    address = int(proxy.SMProxy.__this__[1:].split("_")[0], 16)
    item = find(model, qt.meta(qt.pq, "pqPipelineSource"), address)
    check(item, "no pqPipelineSource for %s" % proxy.GetXMLName())
    set_state = qt.pq._ZN7pqProxy16setModifiedStateENS_13ModifiedStateE
    set_state.argtypes = [ctypes.c_void_p, ctypes.c_int]
    set_state.restype = None
    set_state(item, 1)
    qt.process_events()
