#!/bin/sh
# SPDX-License-Identifier: MIT
# Installs this build with `meson install --destdir` (so into a prefix the build never saw) and
# uses the result the way users do: the installed tool without LD_LIBRARY_PATH (RUNPATH), a C
# program through pkg-config, a CMake project through find_package(circledist CONFIG), and a
# meson project using the source tree as a subproject; checks the installed files (headers,
# .pc, CMake package, man pages, documentation).
# usage: test_install.sh SOURCE_DIR BUILD_DIR SCRATCH_DIR PREFIX LIBDIR BINDIR INCLUDEDIR MANDIR
#                        DATADIR DEFAULT_LIBRARY SANITIZE
set -eu
src=$1 build=$2 scratch=$3 prefix=$4 libdir=$5 bindir=$6 includedir=$7 mandir=$8 datadir=$9
shift 9
default_library=$1 sanitize=$2
case $libdir in /*) ;; *) libdir=$prefix/$libdir ;; esac
case $bindir in /*) ;; *) bindir=$prefix/$bindir ;; esac
case $includedir in /*) ;; *) includedir=$prefix/$includedir ;; esac
case $mandir in /*) ;; *) mandir=$prefix/$mandir ;; esac
case $datadir in /*) ;; *) datadir=$prefix/$datadir ;; esac
passed=0
failed=0
ok() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAIL: $*"; }
check_file() { if [ -e "$1" ]; then ok; else fail "not installed: $1"; fi; }
rm -rf "$scratch"
mkdir -p "$scratch"
dest=$scratch/dest
meson install -C "$build" --destdir "$dest" --no-rebuild >"$scratch/install.log" 2>&1 ||
  { cat "$scratch/install.log"; exit 1; }
lib=$dest$libdir
san=""
[ "$sanitize" = none ] || san="-fsanitize=$sanitize"
unset LD_LIBRARY_PATH || true

# Installed files.
for f in "$dest$includedir/circledist.h" "$dest$includedir/circledist_version.h" "$lib/pkgconfig/circledist.pc" \
  "$lib/cmake/circledist/circledistConfig.cmake" "$lib/cmake/circledist/circledistConfigVersion.cmake" \
  "$dest$mandir/man1/circledist.1" "$dest$mandir/man3/libcircledist.3" "$dest$bindir/circledist" \
  "$dest$datadir/doc/libcircledist/README.md" "$dest$datadir/doc/libcircledist/LICENSE"; do
  check_file "$f"
done
for f in "$src"/docs/*.md; do check_file "$dest$datadir/doc/libcircledist/$(basename "$f")"; done
# The man pages name this build's documentation directory, not a fixed one.
for page in "$dest$mandir/man1/circledist.1" "$dest$mandir/man3/libcircledist.3"; do
  grep -qF "$datadir/doc/libcircledist" "$page" && ok || fail "$page does not name $datadir/doc/libcircledist"
  grep -q '@DOCDIR@' "$page" && fail "$page has an unsubstituted @DOCDIR@" || ok
done
if [ "$default_library" = static ]; then
  check_file "$lib/libcircledist.a"
else
  if [ -L "$lib/libcircledist.so.1" ]; then ok; else fail "no soname link libcircledist.so.1"; fi
fi
# The library depends on libc, libm and threads only (GSL is the tests' reference, never linked).
grep -q '^Requires' "$lib/pkgconfig/circledist.pc" && fail "the .pc has Requires: $(grep '^Requires' "$lib/pkgconfig/circledist.pc")" || ok
grep -qi 'gsl' "$lib/pkgconfig/circledist.pc" "$lib/cmake/circledist/circledistConfig.cmake" && fail "GSL named in the .pc or the CMake package" || ok
if [ "$default_library" != static ]; then
  readelf -d "$lib/libcircledist.so.1" | grep NEEDED | grep -qi gsl && fail "libcircledist.so.1 needs GSL" || ok
fi

# The tool, without LD_LIBRARY_PATH: it finds the installed library through its RUNPATH.
tool=$dest$bindir/circledist
out=$(echo "pc 3 4 12  0 0 0  0 0 1  2" | "$tool" 2>&1) && ok || fail "installed tool failed: $out"
case $out in "12.3693168768529"*) ok ;; *) fail "installed tool answered '$out', want sqrt(153) = 12.36931687685298..." ;; esac
if [ "$default_library" != static ]; then
  readelf -d "$tool" | grep -q 'RUNPATH.*\$ORIGIN' && ok || fail "tool has no \$ORIGIN RUNPATH: $(readelf -d "$tool" | grep PATH)"
  loaded=$(realpath "$(ldd "$tool" | sed -n 's/.*libcircledist.so.1 => \([^ ]*\).*/\1/p')")
  case $loaded in "$lib"/*) ok ;; *) fail "tool loads '$loaded', not the installed library in $lib" ;; esac
fi

# A user program. Exits 0 when the library answers the known distance.
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

# pkg-config (the .pc holds the prefix; the sysroot maps it into the destdir).
static=""
[ "$default_library" = static ] && static="--static"
export PKG_CONFIG_PATH="$lib/pkgconfig" PKG_CONFIG_SYSROOT_DIR="$dest"
# shellcheck disable=SC2086
if cc $san $(pkg-config --cflags circledist) "$scratch/user.c" -o "$scratch/user-pc" $(pkg-config $static --libs circledist); then
  LD_LIBRARY_PATH="$lib" "$scratch/user-pc" && ok || fail "pkg-config user program failed"
else
  fail "pkg-config user program did not build"
fi
unset PKG_CONFIG_PATH PKG_CONFIG_SYSROOT_DIR

# CMake: find_package(circledist CONFIG) and the imported target.
if command -v cmake >/dev/null; then
  mkdir -p "$scratch/cmake"
  cp "$scratch/user.c" "$scratch/cmake/user.c"
  cat >"$scratch/cmake/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.13)
project(user C)
find_package(circledist ${WANT} CONFIG REQUIRED)
add_executable(user user.c)
target_link_libraries(user PRIVATE circledist::circledist)
CMAKE
  if cmake -S "$scratch/cmake" -B "$scratch/cmake/build" -DWANT=1.0 -DCMAKE_PREFIX_PATH="$dest$prefix" \
       -DCMAKE_C_FLAGS="$san" >"$scratch/cmake.log" 2>&1 &&
     cmake --build "$scratch/cmake/build" >>"$scratch/cmake.log" 2>&1; then
    "$scratch/cmake/build/user" && ok || fail "CMake user program failed"
  else
    cat "$scratch/cmake.log"
    fail "CMake project with find_package(circledist 1.0 CONFIG) did not build"
  fi
  # Another major version must not be accepted (SameMajorVersion).
  if cmake -S "$scratch/cmake" -B "$scratch/cmake/build2" -DWANT=2 -DCMAKE_PREFIX_PATH="$dest$prefix" \
       >"$scratch/cmake2.log" 2>&1; then
    fail "find_package(circledist 2 CONFIG) accepted version 1"
  else
    ok
  fi
else
  echo "cmake not found: the CMake package is not tested"
fi

# Meson subproject: dependency('circledist') is the subproject's override.
mkdir -p "$scratch/meson/subprojects"
ln -s "$src" "$scratch/meson/subprojects/circledist"
cp "$scratch/user.c" "$scratch/meson/user.c"
cat >"$scratch/meson/meson.build" <<'MESON'
project('user', 'c')
subproject('circledist')
executable('user', 'user.c', dependencies: dependency('circledist'))
MESON
if meson setup "$scratch/meson/build" "$scratch/meson" --buildtype=plain >"$scratch/meson.log" 2>&1 &&
   meson compile -C "$scratch/meson/build" user >>"$scratch/meson.log" 2>&1; then
  "$scratch/meson/build/user" && ok || fail "meson subproject user program failed"
else
  tail -20 "$scratch/meson.log"
  fail "meson project with the source tree as subproject did not build"
fi

echo "test_install: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
