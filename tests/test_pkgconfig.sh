#!/bin/sh
# SPDX-License-Identifier: MIT
# Installs into a scratch prefix and builds + runs a small C program with
# `pkg-config --cflags --libs circledist`. usage: test_pkgconfig.sh SOURCE_DIR SCRATCH_DIR
set -eu
src=$1
scratch=$2
rm -rf "$scratch"
mkdir -p "$scratch"
prefix="$scratch/prefix"
meson setup "$scratch/build" "$src" -Dprefix="$prefix" -Dlibdir=lib --buildtype=release >"$scratch/setup.log" 2>&1 ||
  { cat "$scratch/setup.log"; exit 1; }
meson install -C "$scratch/build" >"$scratch/install.log" 2>&1 || { cat "$scratch/install.log"; exit 1; }
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
grep -q '^Requires.private: gsl' "$prefix/lib/pkgconfig/circledist.pc" || { echo "gsl not in Requires.private"; exit 1; }
! grep -q '^Requires: ' "$prefix/lib/pkgconfig/circledist.pc" || { echo "public Requires must be empty"; exit 1; }
test -L "$prefix/lib/libcircledist.so.1" || { echo "no soname link"; exit 1; }
test -x "$prefix/bin/circledist" || { echo "tool not installed"; exit 1; }
cat >"$scratch/user.c" <<'C'
#include <circledist.h>
#include <stdio.h>
int main(void)
{
    cdist_query *q = cdist_query_new();
    cdist_circle c = {{0, 0, 0}, {0, 0, 1}, 2};
    cdist_vec3 p = {3, 4, 12};
    cdist_result r;
    if (cdist_point_circle(q, &p, &c, &r) != CDIST_OK) return 1;
    cdist_query_free(q);
    printf("%.17g %s\n", r.distance, cdist_version_string());
    return (r.distance * r.distance > 152.999999 && r.distance * r.distance < 153.000001) ? 0 : 1;
}
C
cc $(pkg-config --cflags circledist) "$scratch/user.c" -o "$scratch/user" $(pkg-config --libs circledist)
LD_LIBRARY_PATH="$prefix/lib" "$scratch/user"
echo "test_pkgconfig: 1 passed, 0 failed"
