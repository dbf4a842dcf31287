#!/bin/sh
# SPDX-License-Identifier: MIT
# Makes the reference state files of this folder: converged fine-mesh runs of the scenes here,
# by `stroma run --export-state`, each file headed by the exact command that made it (comment
# lines after the format line). Run from anywhere; STROMA names the stroma binary (default:
# build/bin/stroma of the repository). See README.md for what each file holds. With ccx
# installed and no scene named, it also remakes calculix/*.state (calculix/cantilever_ccx.py).
#
#   share/reference/make_references.sh            # all of them
#   STROMA=build-release/bin/stroma share/reference/make_references.sh CantileverSmallHexa
set -eu
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
stroma=${STROMA:-$repo/build/bin/stroma}
[ -x "$stroma" ] || { echo "make_references.sh: no stroma binary at $stroma (set STROMA)" >&2; exit 2; }

# scene  steps  export-every: static scenes take one step; the damped dynamic ones keep the
# snapshots at 0, half-way and the end, so that a reader can see the equilibrium reached.
runs="CantileverSmallHexa 1 1
CantileverLargeHexa 60 30
CantileverLargeTetra 60 30"

echo "$runs" | while read -r scene steps every; do
  if [ $# -gt 0 ]; then
    case " $* " in *" $scene "*) ;; *) continue ;; esac
  fi
  out="$here/$scene.state"
  command="stroma run -n $steps --export-every $every --export-state share/reference/$scene.state share/reference/$scene.scn"
  echo "$command" >&2
  (cd "$repo" && "$stroma" run -n "$steps" --export-every "$every" --export-state "$out.tmp" \
    "share/reference/$scene.scn" >/dev/null)
  # The format line first, then the command and the stroma version as comments.
  { head -n 1 "$out.tmp"
    echo "# made by: $command"
    echo "# with: $("$stroma" --version 2>/dev/null || echo stroma) (share/reference/make_references.sh)"
    tail -n +2 "$out.tmp"; } > "$out"
  rm -f "$out.tmp"
done

# CalculiX's runs of the same cantilevers (independent code), when ccx is installed
# (Debian calculix-ccx) and no scene was named.
if [ $# -eq 0 ]; then
  if command -v ccx >/dev/null 2>&1; then
    python3 "$here/calculix/cantilever_ccx.py" --output "$here/calculix/CantileverSmallCalculix.state"
    python3 "$here/calculix/cantilever_ccx.py" --cells 60 6 6 --load 1666.6667 --nlgeom \
      --output "$here/calculix/CantileverLargeCalculix.state"
  else
    echo "make_references.sh: no ccx (calculix-ccx): the CalculiX references were not remade" >&2
  fi
fi
