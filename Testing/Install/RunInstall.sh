#!/bin/sh
# Install test (Testing/Install/CMakeLists.txt): install the build tree into a fresh prefix and
# use every installed piece from a clean environment (env -i PATH=/usr/bin:/bin HOME=..,
# no LD_LIBRARY_PATH, no PYTHONPATH but the installed package), so only the install
# tree's RUNPATHs and files can make it work.
#   RunInstall.sh CMAKE BUILD_DIR PREFIX LIBDIR PLUGIN_SUBDIR PYTHON_DEST BINDIR PYTHON CLOUD
set -eu
cmake=$1 build=$2 prefix=$3 libdir=$4 plugin_subdir=$5 pydest=$6 bindir=$7 python=$8 cloud=$9
plugin_dir="$prefix/$libdir/$plugin_subdir/FlowRecon"
plugin="$plugin_dir/FlowRecon.so"
clean="env -i PATH=/usr/bin:/bin HOME=${HOME:-/tmp}"
fail() { echo "install: FAIL: $*"; exit 1; }

echo "== cmake --install $build --prefix $prefix"
rm -rf "$prefix"
"$cmake" --install "$build" --prefix "$prefix" >"$prefix.log" 2>&1 || { cat "$prefix.log"; fail "cmake --install"; }
for f in "$plugin" "$prefix/$bindir/flowrecon" "$prefix/$pydest/flowrecon/__init__.py"; do
  [ -e "$f" ] || fail "missing $f; installed: $(cd "$prefix" && find . -type f | sort | tr '\n' ' ')"
done

echo "== RUNPATHs of the installed binaries name no build-tree folder"
if command -v readelf >/dev/null; then
  find "$prefix" -type f \( -name '*.so*' -o -path "*/$bindir/*" \) | while read -r f; do
    rp=$(readelf -d "$f" 2>/dev/null | sed -n 's/.*R\(UN\)\{0,1\}PATH.*\[\(.*\)\]/\2/p')
    echo "   ${f#$prefix/}: ${rp:-(none)}"
    case "$rp" in *"$build"*) fail "$f has the build-tree RUNPATH $rp" ;; esac
  done
fi

echo "== (a) pvbatch + LoadPlugin($plugin)"
$clean pvbatch -c "
from paraview.simple import *
LoadPlugin('$plugin', remote=False, ns=globals())
src = PointSource(NumberOfPoints=100, Radius=1.0)
fc = FlowComplex(Input=src)
rc = FlowReconstruction(Input=FlowComplexSimplification(Input=fc))
rc.UpdatePipeline()
n = rc.GetDataInformation().GetNumberOfCells()
assert n > 0, n
print('pvbatch: installed plugin OK,', n, 'reconstruction cells')
" || fail "(a) pvbatch LoadPlugin"

echo "== (b) PV_PLUGIN_PATH=$plugin_dir pvpython, no LoadPlugin"
$clean PV_PLUGIN_PATH="$plugin_dir" pvpython -c "
from paraview import simple
assert hasattr(simple, 'FlowComplex'), 'FlowComplex not auto-loaded from PV_PLUGIN_PATH'
fc = simple.FlowComplex(Input=simple.PointSource(NumberOfPoints=100, Radius=1.0))
fc.UpdatePipeline()
assert fc.GetDataInformation().GetNumberOfPoints() > 0
print('pvpython: PV_PLUGIN_PATH auto-load OK')
" || fail "(b) pvpython PV_PLUGIN_PATH"

echo "== (c) PYTHONPATH=$prefix/$pydest $python: import flowrecon"
$clean PYTHONPATH="$prefix/$pydest" "$python" -c "
import flowrecon
assert flowrecon.__file__.startswith('$prefix/'), flowrecon.__file__
f = flowrecon.vtkFlowComplex()
print('python: import flowrecon OK,', f.GetClassName(), 'from', flowrecon.__file__)
" || fail "(c) import flowrecon"

echo "== (d) $prefix/$bindir/flowrecon"
$clean "$prefix/$bindir/flowrecon" --version || fail "(d) flowrecon --version"
$clean "$prefix/$bindir/flowrecon" reconstruct "$cloud" -o "$prefix/cloud.vtu" -q || fail "(d) flowrecon reconstruct"
[ -s "$prefix/cloud.vtu" ] || fail "(d) no $prefix/cloud.vtu"
echo "install: PASS"
