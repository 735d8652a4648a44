#!/bin/sh
# The external-solver benchmark: see run.py (it installs, builds and runs).
# Uses Debian's python3 (the standard library is all it needs).
exec /usr/bin/python3 "$(dirname "$0")/run.py" "$@"
