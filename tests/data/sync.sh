#!/bin/sh
# SPDX-License-Identifier: MIT
# Where tests/data comes from. Every file here except this script, SHA256SUMS,
# revision2_recomputed.txt and cc_coplanar_dips.* / gen_cc_coplanar_dips.py is a verbatim copy
# of the shared reference cases (../shared/cases, revision 2: README.md says how their expected
# distances were computed, independently of this library). revision2_recomputed.txt is ours:
# the 68 lines revision 2 recomputed, which tests/reference_recomputed.py checks against mpmath.
# cc_coplanar_dips.txt is ours too (nearly coplanar circles with narrow rim-crossing dips inside
# the engine's near-crossing window; its header says where the lines come from), its .expected
# written by gen_cc_coplanar_dips.py (mpmath, independent of the library). SHA256SUMS pins every file; the test
# `data-sums` fails when one changes, so an expected value is never edited to suit the code.
#
# usage: tests/data/sync.sh [CASES_DIR]   copy the shared files again (default ../shared/cases
#                                         next to the repository) and check the sums
#        tests/data/sync.sh --check       check the sums only
set -eu
here=$(cd "$(dirname "$0")" && pwd)
cd "$here"
if [ "${1:-}" != "--check" ]; then
    src=${1:-$here/../../../shared/cases}
    [ -d "$src" ] || { echo "sync.sh: no cases directory $src" >&2; exit 2; }
    for f in $(awk '{print $2}' SHA256SUMS); do
        case $f in revision2_recomputed.txt | cc_coplanar_dips.* | gen_cc_coplanar_dips.py) continue ;; esac
        cp "$src/$f" "$f"
    done
fi
sha256sum --check --quiet SHA256SUMS && echo "tests/data: every file matches SHA256SUMS"
