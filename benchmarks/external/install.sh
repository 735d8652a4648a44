#!/bin/sh
# Install what the external-solver drivers need from Debian bookworm.
# Idempotent: the top-level install.sh with these packages added.
# PETSc (with TAO, SNES VI, CHOLMOD and MUMPS) comes with deal.II
# (libpetsc-real-dev); it is listed so that a machine without it gets it too.
set -e
root=$(cd "$(dirname "$0")/../.." && pwd)
exec "$root/install.sh" pkg-config libpetsc-real-dev libsiconos-numerics-dev \
  coinor-libipopt-dev
