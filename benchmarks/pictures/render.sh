#!/bin/sh
# Make the README pictures doc/pictures/*.png from scratch: install ParaView
# if it is missing, build unilateral, run the scenes of this folder
# into output/pictures/ and render them offscreen with ParaView's pvpython.
#
#   benchmarks/pictures/render.sh        (from anywhere; Debian bookworm)
#
# Idempotent: installs only what is missing, reuses the build.
set -eu

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
cd "$root"
build=${BUILD_DIR:-build}

# --- ParaView -------------------------------------------------------------
# Debian's paraview (5.11) brings pvbatch but not pvpython, which lives in
# python3-paraview. That package conflicts with python3-vtk9, which
# install.sh installs for the tests (both ship the Python module "vtk"), so
# installing it would remove python3-vtk9 and the next install.sh would
# remove it again. Unless python3-paraview is installed already, we unpack it
# privately into $build-pvpython/ instead: its pvpython finds its own Python
# modules next to itself, before the system's. ParaView here is built for X
# only (no EGL or OSMesa), and --force-offscreen-rendering without a display
# crashes, so pvpython runs under Xvfb.
# (ParaView takes about 630 MB.)
./install.sh paraview xvfb

if dpkg-query -W -f='${Status}' python3-paraview 2>/dev/null |
    grep -q "install ok installed"; then
  pvpython=/usr/bin/pvpython
else
  version=$(dpkg-query -W -f='${Version}' paraview)
  private="$root/$build-pvpython"
  pvpython="$private/usr/bin/pvpython"
  if [ "$(cat "$private/version" 2>/dev/null)" != "$version" ]; then
    echo "render.sh: unpacking python3-paraview $version into $private"
    rm -rf "$private"
    mkdir -p "$private"
    (cd "$private" &&
     apt-get download -qq -o APT::Sandbox::User=root \
       "python3-paraview=$version" &&
     dpkg-deb -x python3-paraview_*.deb . &&
     rm python3-paraview_*.deb)
    echo "$version" > "$private/version"
  fi
fi

# --- unilateral -------------------------------------------------------------
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$build" -j2 --target unilateral

# --- the runs: output/pictures/<run name>/ (a failed solve stops here) -----
# The masonry_*.prm of this folder are copies of the examples prm/masonry_*.prm
# but for the output and the mesh file's path: check that they still agree.
settings() {
  sed -e 's/#.*//' -e 's/[[:space:]]*$//' -e '/^$/d' \
      -e '/^ *set \(Directory\|Run name\|Progress\) *=/d' \
      -e 's|\.\./\.\./prm/meshes/|meshes/|' "$1"
}
copy=$(mktemp)
for example in masonry_arch masonry_window masonry_wall_3d \
    masonry_barrel_vault; do
  settings "benchmarks/pictures/$example.prm" > "$copy"
  if ! settings "prm/$example.prm" | diff - "$copy" > /dev/null; then
    echo "render.sh: benchmarks/pictures/$example.prm no longer has the" \
      "settings of prm/$example.prm: copy them over" >&2
    rm -f "$copy"
    exit 1
  fi
done
rm -f "$copy"
for scene in wall_stack_bond wall_running_bond wall_laminae plate_psi3 \
    masonry_arch masonry_window masonry_wall_3d masonry_barrel_vault; do
  echo "render.sh: running benchmarks/pictures/$scene.prm"
  "$build/unilateral" "benchmarks/pictures/$scene.prm" > /dev/null
done

# --- the pictures -----------------------------------------------------------
# Our own Xvfb rather than xvfb-run -a, whose guess of a free display number
# races with other X servers on a shared machine (seen once: "bad X server
# connection"). With -displayfd the server picks a free number itself and
# writes it once it accepts connections.
echo "render.sh: rendering into doc/pictures/"
display_file=$(mktemp)
Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp 3>"$display_file" &
xvfb=$!
trap 'kill $xvfb 2>/dev/null; rm -f "$display_file"' EXIT
waited=0
while [ ! -s "$display_file" ]; do
  waited=$((waited + 1))
  if [ $waited -gt 300 ] || ! kill -0 $xvfb 2>/dev/null; then
    echo "render.sh: Xvfb did not start" >&2
    exit 1
  fi
  sleep 0.1
done
DISPLAY=":$(cat "$display_file")" \
  "$pvpython" "$here/render.py" output/pictures doc/pictures
ls -l doc/pictures/*.png
