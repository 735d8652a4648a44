#!/bin/sh
# Install what unilateral needs from Debian bookworm, if it is missing.
# Idempotent: does nothing (and needs no network) when all is present.
#
#   ./install.sh                 what the build and the tests need
#   ./install.sh PACKAGE...      that, and these (the benchmark scripts)
set -e

packages="cmake g++ make libdeal.ii-dev libeigen3-dev libsuitesparse-dev \
numdiff libopenblas0-pthread openmpi-bin python3-vtk9 python3-numpy $*"

missing=""
for package in $packages; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing="$missing $package"
  fi
done

if [ "$(id -u)" -eq 0 ]; then sudo=""; else sudo="sudo"; fi
if [ -n "$missing" ]; then
  echo "install.sh: installing$missing"
  # Another apt-get may hold the dpkg lock (a shared machine): wait for it
  # (apt-get's own lock timeout) and retry a few times rather than fail.
  attempt=1
  while ! { $sudo apt-get -o DPkg::Lock::Timeout=120 update -qq &&
            DEBIAN_FRONTEND=noninteractive $sudo apt-get \
              -o DPkg::Lock::Timeout=300 install -y -qq \
              --no-install-recommends $missing; }; do
    if [ "$attempt" -ge 5 ]; then
      echo "install.sh: apt-get failed $attempt times" >&2
      exit 1
    fi
    echo "install.sh: apt-get failed (lock held?); retrying in 30 s" >&2
    attempt=$((attempt + 1))
    sleep 30
  done
fi

# CHOLMOD's supernodal factorisation lives in BLAS: make sure the optimised
# OpenBLAS is the one selected (about 5x faster than the reference BLAS).
for library in libblas.so.3 liblapack.so.3; do
  alternative="$library-x86_64-linux-gnu"
  target="/usr/lib/x86_64-linux-gnu/openblas-pthread/$library"
  if [ -e "$target" ] && update-alternatives --query "$alternative" 2>/dev/null |
      grep -q "^Value: " && ! update-alternatives --query "$alternative" |
      grep -q "^Value: $target"; then
    $sudo update-alternatives --set "$alternative" "$target" >/dev/null
  fi
done
