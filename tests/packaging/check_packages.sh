#!/usr/bin/env bash
# Builds the Debian packages as a user would (cpack -G DEB) and checks what
# is in them: tetskin has the executables, the data, the desktop entry and
# Netgen's module (found from the packaged tetskin) and does not depend on
# ParaView, and (where the Python module was built) has
# it where Debian's python3 imports it from; where the ParaView plugin was built,
# tetskin-paraview-plugin has it beside ParaView's own plugins, depends on
# paraview 5.11, and ParaView loads it from there on its own (PV_PLUGIN_PATH,
# the way the README gives).
# Usage: check_packages.sh CPACK BUILD_DIR GUI(0|1) PLUGIN(0|1) PYTHON(0|1) [PARAVIEW_ROOT CHECKS_DIR]
set -euo pipefail
build=$(cd "$2" && pwd)
cpack=$1 gui=$3 plugin=$4 python=$5 pvroot=${6:-} checks=${7:-}
out=$build/package

fail() {
  echo "FAIL: $*"
  exit 1
}
has() {  # has PACKAGE PATH: the package installs PATH
  dpkg-deb -c "$1" | awk '{print $6}' | grep -qx "./$2" || fail "$(basename "$1") lacks /$2"
}

rm -rf "$out"
(cd "$build" && "$cpack" -G DEB -B "$out") || fail "cpack failed"

main=$(find "$out" -maxdepth 1 -name 'tetskin_*.deb')
[[ -n $main ]] || fail "no tetskin_*.deb in $out"
has "$main" usr/bin/tetskin
[[ $gui == 1 ]] && has "$main" usr/bin/tetskin-gui
has "$main" usr/share/tetskin/data/bunny.json
has "$main" usr/share/applications/tetskin.desktop
has "$main" usr/share/doc/tetskin/LICENSE
has "$main" usr/share/doc/tetskin/doc/user/model-generation.md
depends=$(dpkg-deb -f "$main" Depends)
[[ $depends == *libvtk9.1* ]] || fail "tetskin does not depend on libvtk9.1: $depends"
[[ $depends != *paraview* ]] || fail "tetskin depends on ParaView: $depends"
# (The listing is kept: grep -q on a pipe would end dpkg-deb early, which
# pipefail counts as a failure.)
listing=$(dpkg-deb -c "$main")
# (Unpacked outside the build folder: what runs from there takes the
# build's own module.)
unpackedMain=$(mktemp -d)
trap 'rm -rf "$unpackedMain"' EXIT
dpkg-deb -x "$main" "$unpackedMain"
# Netgen's module (loaded when first used), and that the packaged tetskin
# finds it where the package puts it: a Netgen build runs.
if [[ -f $build/modules/meshing/libtetskin_netgen.so ]]; then
  has "$main" usr/lib/tetskin/libtetskin_netgen.so
  "$unpackedMain/usr/bin/tetskin" build "$(dirname "$0")/../data/cube_0.obj" \
    -o "$out/netgen_cube" --mesher netgen --levels 1 --min-elements 10 --max-elements 200 -q >/dev/null ||
    fail "the packaged tetskin does not mesh with Netgen"
fi
if [[ $python == 1 ]]; then
  has "$main" usr/lib/python3/dist-packages/tetskin/__init__.py
  # The module, its VTK filters, and that Debian's python3 imports them from
  # where the package puts them.
  grep -q "dist-packages/tetskin/_tetskin.cpython-.*\.so" <<<"$listing" ||
    fail "tetskin lacks the Python module's library"
  grep -q "dist-packages/tetskin/vtkTetSkinFilters.*\.so" <<<"$listing" ||
    fail "tetskin lacks the VTK filters' Python module"
  [[ $depends == *python3-numpy* ]] || fail "tetskin does not depend on python3-numpy: $depends"
  ! grep -q "\.a$" <<<"$listing" || fail "tetskin holds a static library"
  PYTHONPATH=$unpackedMain/usr/lib/python3/dist-packages /usr/bin/python3 -c \
    "import tetskin, tetskin.vtk; tetskin.vtk.vtkTetSkinBindSurface()" ||
    fail "the packaged Python module does not import"
fi
echo "tetskin: $(dpkg-deb -c "$main" | wc -l) entries, python module: $python"

pluginDeb=$(find "$out" -maxdepth 1 -name 'tetskin-paraview-plugin_*.deb')
if [[ $plugin == 0 ]]; then
  [[ -z $pluginDeb ]] || fail "a plugin package without a built plugin: $pluginDeb"
  echo "PASS: tetskin (no ParaView plugin in this build)"
  exit 0
fi
[[ -n $pluginDeb ]] || fail "no tetskin-paraview-plugin_*.deb in $out"
arch=$(dpkg-architecture -qDEB_HOST_MULTIARCH)
so=usr/lib/$arch/paraview-5.11/plugins/TetSkinFilters/TetSkinFilters.so
has "$pluginDeb" "$so"
depends=$(dpkg-deb -f "$pluginDeb" Depends)
[[ $depends == *"paraview (>= 5.11"* ]] || fail "the plugin does not depend on paraview 5.11: $depends"
echo "tetskin-paraview-plugin: depends on $depends"

if [[ -n $pvroot ]]; then
  unpacked=$out/unpacked
  dpkg-deb -x "$pluginDeb" "$unpacked"
  PV_PLUGIN_PATH=$(dirname "$unpacked/$so") "$pvroot/usr/bin/pvpython" \
    "$checks/pvwrapper.py" "$pvroot" "$checks/check_plugin_loads.py" ||
    fail "ParaView did not load the packaged plugin"
fi
echo "PASS: tetskin and tetskin-paraview-plugin"
