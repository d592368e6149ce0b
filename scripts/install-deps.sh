#!/bin/sh
# SPDX-License-Identifier: MIT
# Installs the build and test dependencies on Debian 12 (run as root). Idempotent: packages
# already present are not fetched again.
set -eu
# libgsl-dev: the tests' reference for the polynomial solver (the library does not link GSL)
pkgs="meson ninja-build pkg-config gcc g++ libgsl-dev binutils python3 python3-numpy python3-mpmath python3-pytest abigail-tools cmake"
# libFuzzer with ASan/UBSan (scripts/fuzz.sh): clang and its runtime libraries
pkgs="$pkgs clang-14 libclang-rt-14-dev"
# the Python package: meson-python wheel test, examples (Dask chain mail, matplotlib picture)
pkgs="$pkgs python3-setuptools python3-pip python3-venv python3-wheel python3-mesonpy mypy doxygen python3-dask python3-distributed python3-matplotlib"
# the protein example: a PDB file (pymol-data) and the heuristic it is compared with (plip)
pkgs="$pkgs pymol-data plip"
missing=""
for p in $pkgs; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update
  # shellcheck disable=SC2086
  apt-get install -y --no-install-recommends $missing
fi
