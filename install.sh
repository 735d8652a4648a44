#!/bin/sh
# Install what unilateral needs from Debian bookworm, if it is missing.
# Idempotent: does nothing (and needs no network) when all is present.
set -e

packages="cmake g++ make libdeal.ii-dev libeigen3-dev libsuitesparse-dev \
numdiff libopenblas0-pthread python3-vtk9 python3-numpy"

missing=""
for package in $packages; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing="$missing $package"
  fi
done

if [ -n "$missing" ]; then
  echo "install.sh: installing$missing"
  if [ "$(id -u)" -eq 0 ]; then sudo=""; else sudo="sudo"; fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq \
    --no-install-recommends $missing
fi

# CHOLMOD's supernodal factorisation lives in BLAS: make sure the optimised
# OpenBLAS is the one selected (about 5x faster than the reference BLAS).
for library in libblas.so.3 liblapack.so.3; do
  alternative="$library-x86_64-linux-gnu"
  target="/usr/lib/x86_64-linux-gnu/openblas-pthread/$library"
  if [ -e "$target" ] && update-alternatives --query "$alternative" 2>/dev/null |
      grep -q "^Value: " && ! update-alternatives --query "$alternative" |
      grep -q "^Value: $target"; then
    if [ "$(id -u)" -eq 0 ]; then sudo=""; else sudo="sudo"; fi
    $sudo update-alternatives --set "$alternative" "$target" >/dev/null
  fi
done
