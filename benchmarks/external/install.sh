#!/bin/sh
# Install what the external-solver drivers need from Debian bookworm.
# Idempotent: asks dpkg first and does nothing (no network) when all is there.
# PETSc (with TAO, SNES VI, CHOLMOD and MUMPS) comes with deal.II
# (libpetsc-real-dev); it is listed so that a machine without it gets it too.
set -e

packages="cmake g++ make pkg-config libpetsc-real-dev \
libsiconos-numerics-dev coinor-libipopt-dev libeigen3-dev libsuitesparse-dev"

missing=""
for package in $packages; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null |
      grep -q "install ok installed"; then
    missing="$missing $package"
  fi
done
[ -z "$missing" ] && exit 0

echo "benchmarks/external/install.sh: installing$missing"
if [ "$(id -u)" -eq 0 ]; then sudo=""; else sudo="sudo"; fi

# The machine is shared: another apt-get may hold the dpkg lock. Wait for it
# (apt-get's own lock timeout) and retry a few times rather than fail.
attempt=1
while :; do
  if $sudo apt-get -o DPkg::Lock::Timeout=120 update -qq &&
     DEBIAN_FRONTEND=noninteractive $sudo apt-get -o DPkg::Lock::Timeout=300 \
       install -y -qq --no-install-recommends $missing; then
    break
  fi
  if [ "$attempt" -ge 5 ]; then
    echo "benchmarks/external/install.sh: apt-get failed $attempt times" >&2
    exit 1
  fi
  echo "benchmarks/external/install.sh: apt-get failed (lock held?);" \
       "retrying in 30 s" >&2
  attempt=$((attempt + 1))
  sleep 30
done
